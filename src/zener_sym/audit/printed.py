"""The paper's printed items, transcribed as they are printed (data only).

Each item has an ``id`` (the equation number as a string, a symbol name for an unnumbered
definition, ``claim:<name>`` for a numeric claim of the text), a ``kind`` (equation, definition,
claim), the ``raw`` text of the transcription and ``parse``: a SymPy-readable transcription of what
is printed, *exponents and constants exactly as printed*, or None where the printed text cannot be
read as a formula (the item is then ``garbled``), or where the item is a claim in words.

``parse`` strings use the names of :data:`NS`. A relation is written ``Eq(lhs, rhs)``; a
quantity defined by the item is written as its right-hand side (``reads`` says which quantity).
Nothing here is corrected: the corrections live in the derivation and in the audit's evidence.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, TypedDict

import sympy as sp

from ._raw import RAW_EQUATIONS

__all__ = ["Printed", "ITEMS", "NS", "SYM", "by_id", "parse", "numbers", "Expr"]

#: A SymPy expression. SymPy ships no type information, so this is ``Any`` under a name that says
#: what the value is.
Expr = Any

# Dimensionless core (positive: the audit samples them in their physical range).
lam, tau, k, beta, omega0, p, x, y, dm = sp.symbols("lam tau k beta omega0 p x y dm", positive=True)
# Physical symbols: masses, moduli, Poisson ratios, densities, lengths, speeds, time.
(m1, mh, m2, ms, Es, E1, E2, nu1, nu2, rho1, rho2, R, H, V0, t, kc) = sp.symbols(
    "m1 mh m2 ms Es E1 E2 nu1 nu2 rho1 rho2 R H V0 t kc", positive=True)
(T, alpha, V_W, chi, I, W, w, F, V, tau_d) = sp.symbols(
    "T alpha V_W chi I W w F V tau_d", positive=True)
d = sp.Function("d")      # dimensionless delta-bar(tau) (or delta(t) in the physical equations)
d0 = sp.Function("d0")    # delta-bar_0(tau)
d1 = sp.Function("d1")    # delta-bar_1(tau)
yf = sp.Function("yf")    # y(delta) of Eq. (17)
C11 = sp.Function("C11")
C12 = sp.Function("C12")
G = sp.Function("G")      # the paper's G(a, b; c; z) = 2F1
Ff = sp.Function("Ff")    # the contact force F(t) in Eq. (7)

SYM = {s.name: s for s in (lam, tau, k, beta, omega0, p, x, y, dm, m1, mh, m2, ms, Es, E1, E2,
                            nu1, nu2, rho1, rho2, R, H, V0, t, kc, T, alpha, V_W, chi, I, W, w, F,
                            V, tau_d)}
NS = dict(SYM, Ff=Ff, d=d, d0=d0, d1=d1, yf=yf, C11=C11, C12=C12, G=G, Eq=sp.Eq, Derivative=sp.Derivative,
          Integral=sp.Integral, exp=sp.exp, sin=sp.sin, cos=sp.cos, sqrt=sp.sqrt, pi=sp.pi,
          atan=sp.atan, I_=sp.I, Rational=sp.Rational, E_=sp.E)


@dataclass(frozen=True)
class Printed:
    """One printed item: what the paper prints, transcribed without correction."""

    id: str
    kind: str  # "equation", "definition" or "claim"
    raw: str
    parse: str | None
    reads: str = ""  # which quantity/relation the parse is (for the table)


def _eq(n: int, parse: str | None, reads: str = "") -> Printed:
    return Printed(str(n), "equation", RAW_EQUATIONS[str(n)], parse, reads)


def _def(name: str, raw: str, parse: str | None, reads: str = "") -> Printed:
    return Printed(name, "definition", raw, parse, reads)


def _claim(name: str, raw: str, numbers: str, reads: str) -> Printed:
    # ``numbers``: the printed number(s) of the claim, comma-separated, digits exactly as printed
    return Printed("claim:" + name, "claim", raw, numbers, reads)


R_ = "Rational"
ITEMS: tuple[Printed, ...] = (
    _eq(1, "Eq(Derivative(d(t), t, 2) + kc*d(t)**3, 0)", "Hertz's equation of impact"),
    _eq(2, "2.94*(Rational(15,16)*m1*mh/(m1 + mh)/Es)**Rational(2,3)*R**Rational(1,3)"
           "*V0**Rational(-1,3)", "T_Hertz"),
    _eq(3, "(Rational(15,16)*m1*mh/(m1 + mh)/Es)**Rational(2,3)*R**Rational(-1,3)"
           "*V0**Rational(4,3)", "delta_m (Hertz, physical)"),
    _eq(4, "dm*sin(1.068*V0/dm*t)", "delta(t) of Hunter (dm = delta_m)"),
    _eq(5, "-m1*dm*(1.068*V0/dm)**2*sin(1.068*V0/dm*t)", "F(t) of Hunter"),
    _eq(6, "-Rational(4,3)*R**Rational(1,2)*Es*dm**Rational(3,2)*sin(1.068*V0/dm*t)**Rational(3,2)",
        "F(t) of Reed"),
    _eq(7, "Eq(Derivative(d(t), t, 2) + Ff(t)/ms + alpha*Derivative(Ff(t), t), 0)",
        "Zener's equation (Ff(t) = F(delta(t)))"),
    _eq(8, "Rational(4,3)*Es*R**Rational(1,2)*d(t)**Rational(3,2)", "F(delta), Hertz's law"),
    _eq(9, None, "delta-bar = delta/(T V0), tau = t/T (definitions of the scales)"),
    _eq(10, "Eq(Derivative(d(tau), tau, 2) + d(tau)**Rational(3,2)"
            " + lam*Derivative(d(tau)**Rational(3,2), tau), 0)", "Zener's equation, dimensionless"),
    _eq(11, None, "lambda in materials and geometry"),
    _eq(12, "Derivative(d(tau), tau, 2) + k*d(tau) + lam*k*Derivative(d(tau), tau)", "L(delta)"),
    _eq(13, "Derivative(d(tau), tau, 2) + d(tau)**Rational(3,2)"
            " + lam*Derivative(d(tau)**Rational(3,2), tau)", "N(delta)"),
    _eq(14, None, "zero-order deformation equation (definition)"),
    _eq(15, "(1 - p)*(Derivative(d(tau), tau, 2) + k*lam*Derivative(d(tau), tau) + k*d(tau))"
            " + p*(Derivative(d(tau), tau, 2) + Rational(3,2)*lam*sqrt(d(tau))*Derivative(d(tau), tau)"
            " + d(tau)**Rational(3,2))", "left side of (15)"),
    _eq(16, None, "series in p (definition)"),
    _eq(17, "yf(x)*Derivative(yf(x), x) + Rational(3,2)*lam*sqrt(x)*yf(x) + x**Rational(3,2)",
        "left side of (17), x = delta-bar"),
    _eq(18, "Derivative(yf(x), x) + Rational(3,2)*lam*sqrt(x)", "left side of (18)"),
    _eq(19, "1 - lam*x**Rational(3,2)", "y(delta), lambda -> infinity"),
    _eq(20, "lam", "delta_m**(-3/2), lambda -> infinity"),
    _eq(21, "yf(x)*Derivative(yf(x), x) + x**Rational(3,2)", "left side of (21)"),
    _eq(22, "sqrt(1 - Rational(4,5)*x**Rational(5,2))", "y(delta), lambda -> 0"),
    _eq(23, "Rational(5,4)**Rational(2,5)", "delta_m, lambda -> 0"),
    _eq(24, "lam + Rational(5,4)**Rational(-3,2)", "delta_m**(-3/2)"),
    _eq(25, "(lam + Rational(5,4)**Rational(-3,2))**Rational(-1,3)", "k(lambda)"),
    _eq(26, "sqrt(d0(tau)) + Rational(1,2)*d1(tau)/sqrt(d0(tau))*p"
            " - Rational(1,8)*d1(tau)**2/d0(tau)**1.5*p**2", "sqrt(d0 + p d1) to O(p^2)"),
    _eq(27, "d0(tau)**Rational(3,2) + Rational(3,2)*sqrt(d0(tau))*p"
            " + Rational(3,8)*d1(tau)**2/sqrt(d0(tau))*p**2", "(d0 + p d1)**(3/2) to O(p^2)"),
    _eq(28, "Derivative(d0(tau), tau, 2) + k*lam*Derivative(d0(tau), tau) + k*d0(tau)",
        "left side of (28)"),
    _eq(29, "(0, 1)", "(d0(0), d0'(0))"),
    _eq(30, "Eq(Derivative(d1(tau), tau, 2) + k*lam*Derivative(d1(tau), tau) + k*d1(tau),"
            " -(Derivative(d0(tau), tau, 2) + Rational(3,2)*lam*sqrt(d0(tau))*Derivative(d0(tau), tau)"
            " + d0(tau)**Rational(3,2)))", "equation for delta_1"),
    _eq(31, "(0, 0)", "(d1(0), d1'(0))"),
    _eq(32, "lam/2*(lam + Rational(5,4)**Rational(1,5))**Rational(-1,5)", "beta(lambda)"),
    _eq(33, "sqrt(4*(lam + Rational(5,4)**Rational(1,5))**Rational(-1,5)"
            " - lam**2*(lam + Rational(5,4)**Rational(1,5))**Rational(-1,5))/2", "omega0(lambda)"),
    _eq(34, "exp(-beta*tau)*(y*sin(omega0*tau) + x*cos(omega0*tau))",
        "general solution of (28) (c1 = y, c2 = x)"),
    _eq(35, "exp(-beta*tau)*sin(omega0*tau)/omega0", "delta_0(tau)"),
    _eq(36, "(omega0**2 - beta**2)/omega0*exp(-beta*tau)*sin(omega0*tau)"
            " + 2*beta*exp(-beta*tau)*cos(omega0*tau)"
            " - Rational(3,2)*lam*sqrt(1/omega0)*exp(-3*beta*tau/2)*sqrt(sin(omega0*tau))*cos(omega0*tau)"
            " + (Rational(3,2)*lam*beta - 1)*(1/omega0)**Rational(3,2)*exp(-3*beta*tau/2)"
            "*sin(omega0*tau)**Rational(3,2)", "forcing f(tau)"),
    _eq(37, None, "variation-of-constants ansatz"),
    _eq(38, "Eq(Derivative(C11(tau), tau)*cos(omega0*tau) - Derivative(C12(tau), tau)*sin(omega0*tau),"
            " exp(beta*tau)*F/omega0)",
        "second line of (38) (first line: the usual constraint); F stands for f(tau)"),
    _eq(39, "cos(omega0*tau)/omega0*exp(beta*tau)*F", "C11'(tau) (F stands for f(tau))"),
    _eq(40, "(omega0**2 - beta**2)/omega0**2*x + 2*beta/omega0*y"
            " - 3*lam/(2*omega0**Rational(3,2))*C11(tau) + (3*lam*beta - 2)/(2*omega0**Rational(3,2))*C12(tau)",
        "C11 = ... (x = C111, y = C112, C11(tau) = C113, C12(tau) = C114 as placeholders)"),
    _eq(41, "-(omega0**2 - beta**2)/omega0**2*x - 2*beta/omega0*y"
            " + 3*lam/(2*omega0**Rational(3,2))*C11(tau) - (3*lam*beta - 2)/(2*omega0**Rational(3,2))*C12(tau)",
        "C12 = ... (x = C121, y = C122, C11(tau) = C123, C12(tau) = C124 as placeholders)"),
    _eq(42, "d0(tau) + (C11(tau) - C11(0))*exp(-beta*tau)*sin(omega0*tau)"
            " + (C12(tau) - C12(0))*exp(-beta*tau)*cos(omega0*tau)", "delta = delta_0 + delta_1"),
    _eq(43, "(Rational(4,3)*Es*R**Rational(1,2))**Rational(2,3)*ms**Rational(2,3)*V0**Rational(6,3)",
        "force scale F / F-bar"),
    _eq(44, "(Rational(4,3)*Es*R**Rational(1,2))**Rational(2,3)*ms**Rational(2,3)*V0**Rational(6,3)",
        "force scale (denominator of F-bar)"),
    _eq(45, "d(tau)**Rational(3,2)", "F-bar"),
    _eq(46, "Integral(Ff(t), t)", "I (definition)"),
    _eq(47, None, "I-bar = integral of F-bar dtau (definition)"),
    _eq(48, "ms*V0", "impulse scale I / I-bar"),
    _eq(49, "sin(omega0*tau)/(2*omega0)", "delta_1 at lambda = 0 minus the C^d terms"),
    _eq(50, "0.966*sin(1.023*tau)**Rational(3,5)", "F-bar, zeroth order, lambda = 0"),
    _eq(51, "(1.467*sin(1.023*tau) + C11(tau)*sin(1.023*tau) + C12(tau)*cos(1.023*tau))**Rational(3,5)",
        "F-bar, first order, lambda = 0 (C11 = C11^d, C12 = C12^d)"),
    _eq(52, "1.043*sin(0.977*tau)", "F-bar of Hunter"),
    _eq(53, "1.143*sin(0.977*tau)**3", "F-bar of Reed"),
    _eq(54, "2*pi/sqrt(4*(lam + Rational(5,4)**Rational(-3,5))**Rational(1,3)"
            " - (lam + Rational(5,4)**Rational(-3,5))**Rational(2,3)*lam**2)", "tau_d(lambda), zeroth order"),
    _eq(55, "3.214*exp(0.23*lam**1.80)", "tau_d fit"),
    _eq(56, "-beta/omega0*exp(-beta*tau)*sin(omega0*tau) + exp(-beta*tau)*cos(omega0*tau)",
        "delta_0'(tau)"),
    _eq(57, "-beta/omega0*exp(-beta*tau)*sin(omega0*tau) + exp(-beta*tau)*cos(omega0*tau)",
        "left side of (57) at tau = tau_dc"),
    _eq(58, "atan(omega0/beta)/omega0", "tau_dc"),
    _eq(59, "2*atan(sqrt(4/lam**2*(lam + Rational(5,4)**Rational(3,5))**Rational(1,3) - 1))"
            "/sqrt(4*(lam + Rational(5,4)**Rational(3,5))**Rational(1,3)"
            " - (lam + Rational(5,4)**Rational(3,5))**Rational(1,3)*lam**2)", "tau_dc(lambda)"),
    _eq(60, "(2*pi - 2*atan(sqrt(4/lam**2*(lam + Rational(5,4)**Rational(-3,5))**Rational(1,3) - 1)))"
            "/sqrt(4*(lam + Rational(5,4)**Rational(-3,5))**Rational(1,3)"
            " - (lam + Rational(5,4)**Rational(-3,5))**Rational(2,3)*lam**2)", "tau_dr(lambda)"),
    _eq(61, "pi/atan(sqrt(4/lam**2*(lam + Rational(5,4)**Rational(-3,5))**Rational(1,3) - 1)) - 1",
        "eta(lambda)"),
    _eq(62, "m1*V0 - I", "m1 V(t)"),
    _eq(63, "m1*V0 - ms*V0*x", "m1 V(tau) (x = I-bar)"),
    _eq(64, "1 - x", "V-bar (x = I-bar)"),
    _eq(65, "1/(4*rho2*H**2)*sqrt(3*rho2*(1 - nu2**2)/E2)*I", "w (plate deflection)"),
    _eq(66, "ms*V0/(4*rho2*H**2)*sqrt(3*rho2*(1 - nu2**2)/E2)", "deflection scale w / w-bar"),
    _eq(67, "Rational(1,2)*m1*(V0**2 - V**2)", "W (kinetic energy lost)"),
    _eq(68, "W/(Rational(1,2)*m1*V0**2)", "xi (definition)"),
    _eq(69, "2*x - x**2", "xi in I-bar (x = I-bar)"),
    _eq(70, "1 - exp(-2.755*lam)", "xi fit"),
    _eq(71, "2.755*lam - 3.795*lam**2 + 3.485*lam**3 - 2.400*lam**4", "expansion of (70)"),
    _eq(72, "(R/H)**2*V0**0.2", "xi is proportional to (small lambda)"),
    _eq(73, "Integral(Ff(t), w)", "W (definition)"),
    _eq(74, "1/(4*rho2*H**2)*sqrt(3*rho2*(1 - nu2**2)/E2)*x",
        "W (second line; x = integral of F^2 dt; the first line's 'dl' reads as dI)"),
    _eq(75, "Rational(1,2)*chi*ms*V0**Rational(11,3)*(R/H)**2*x", "W (x = integral of F-bar^2 dtau)"),
    _eq(76, "chi*V0**Rational(1,2)*(R/H)**2*x", "xi (x = integral of F-bar^2 dtau)"),
    _eq(77, "1.78*chi*V0**Rational(1,2)*(R/H)**2", "xi, small lambda"),
    _eq(78, "exp(-k*lam/2*tau)", "|d delta_0/d tau| at tau = tau_d"),
    _eq(79, "exp(-pi*lam/sqrt(4/k - lam**2))", "e, zeroth order"),
    _eq(80, "exp(-pi*lam/sqrt(4*(lam + Rational(5,4)**Rational(-1,3))**Rational(1,3) - lam**2))",
        "e(lambda), zeroth order"),
    _eq(81, "4*(lam + Rational(5,4)**Rational(-1,3))**Rational(1,3) - lam**2",
        "left minus right side of (81), > 0"),
    # Unnumbered definitions
    _def("T", r"T = \left( \frac{m^*}{\frac{4}{3}E^*\sqrt{RV_0}} \right)^{\frac{2}{3}}",
         "(ms/(Rational(4,3)*Es*sqrt(R*V0)))**Rational(2,3)", "characteristic time"),
    _def("alpha", r"\alpha = \frac{1}{4\rho_2 H^2} \sqrt{\frac{3\rho_2(1-\nu_2^2)}{E_2}}",
         "1/(4*rho2*H**2)*sqrt(3*rho2*(1 - nu2**2)/E2)", "Zener's coefficient"),
    _def("V_W", r"V_W = \sqrt{E_2/\rho_2(1 - \nu_2^2)}",
         "sqrt(E2/(rho2*(1 - nu2**2)))", "plate wave speed (E2/rho2(1-nu2^2) read as E2/(rho2(1-nu2^2)))"),
    _def("chi", r"\chi = \frac{2\pi^{\frac{3}{2}}}{3^{\frac{1}{2}}} \sqrt{\frac{\rho_2(1-\nu_2^2)}{E_2}}"
                r" \left(\frac{E^*}{\rho_2}\right)^{\frac{2}{3}} \left(\frac{\rho_1}{\rho_2}\right)^{\frac{2}{3}}",
         "2*pi**Rational(3,2)/sqrt(3)*sqrt(rho2*(1 - nu2**2)/E2)*(Es/rho2)**Rational(2,3)"
         "*(rho1/rho2)**Rational(2,3)", "material coefficient of (75)"),
    _def("C111", r"C_{111} = -\frac{\cos^2(\omega_0\tau)}{2\omega_0}", "-cos(omega0*tau)**2/(2*omega0)"),
    _def("C112", r"C_{112} = \frac{\tau}{2} + \frac{\sin(2\omega_0\tau)}{4\omega_0}",
         "tau/2 + sin(2*omega0*tau)/(4*omega0)"),
    _def("C113", r"C_{113} = \frac{1}{2(\beta^2 + 25\omega_0^2)} \left( 2e^{-\frac{1}{2}\beta\tau} \sqrt{\sin(\omega_0\tau)}"
                 r" (\beta\cos(2\omega_0\tau) - 5\omega_0\sin(2\omega_0\tau)) - \frac{(1+i)e^{-\frac{1}{2}\tau(\beta+i\omega_0)}}"
                 r"{(\beta+i\omega_0)(\beta-3i\omega_0)} \left( (\beta^3 - 4i\beta^2\omega_0 + 17\beta\omega_0^2 - 60i\omega_0^3)"
                 r" G\left(1, \frac{i\beta}{2}, \frac{1}{4\omega_0} - \frac{1}{4} \frac{i\beta}{4\omega_0} + \frac{3}{4}"
                 r" e^{2i\omega_0\tau}\right) - (\beta^3 + 2i\beta^2\omega_0 + 19\beta\omega_0^2 + 20i\omega_0^3)"
                 r" e^{2i\omega_0\tau} G\left(1, \frac{i\beta}{2}, \frac{3}{4} \frac{i\beta}{4\omega_0} + \frac{7}{4}"
                 r" e^{2i\omega_0\tau}\right) \right) \right)", None),
    _def("C114", r"C_{114} = \frac{\sqrt{\sin(\omega_0\tau)}}{\beta^2 + 25\omega_0^2} \frac{\omega_0 e^{-\frac{\beta}{2}\tau}}"
                 r"{(\beta+i\omega_0)(\beta-3i\omega_0)} \left( (-\beta^2 + 8i\beta\omega_0 + 15\omega_0^2) G\left(1,"
                 r" \frac{i\beta}{4\omega_0} + \frac{1}{4} \frac{i\beta}{4\omega_0} + \frac{3}{4} e^{2i\omega_0\tau}\right)"
                 r" + e^{2i\omega_0\tau} (\beta^2 + 6i\beta\omega_0 - 5\omega_0^2) G\left(1, \frac{i\beta}{4\omega_0} +"
                 r" \frac{5}{4} \frac{i\beta}{4\omega_0} + \frac{7}{4} e^{2i\omega_0\tau}\right) \right) \beta"
                 r" e^{-\frac{\beta}{2}\tau} \sin(2\omega_0\tau) - 5\omega_0 e^{-\frac{\beta}{2}\tau} \cos(2\omega_0\tau)", None),
    _def("C121", r"C_{121} = \frac{\tau}{2} - \frac{\sin(2\omega_0\tau)}{4\omega_0}",
         "tau/2 - sin(2*omega0*tau)/(4*omega0)"),
    _def("C122", r"C_{122} = C_{111}", "-cos(omega0*tau)**2/(2*omega0)"),
    _def("C123", r"C_{123} = C_{114}", None, "the same function as C114 (garbled there)"),
    _def("C124", r"C_{124} = \frac{2e^{-\frac{\beta}{2}\tau}(e^{2i\omega_0\tau} - 1)}{\beta + 5i\omega_0}"
                 r" \sin^{\frac{5}{2}}(\omega_0\tau) G\left(1, \frac{i\beta}{4\omega_0} + \frac{9}{4};"
                 r" \frac{i\beta}{4\omega_0} - \frac{1}{4}; e^{2i\omega_0\tau}\right)",
         "2*exp(-beta*tau/2)*(exp(2*I_*omega0*tau) - 1)/(beta + 5*I_*omega0)*sin(omega0*tau)**Rational(5,2)"
         "*G(1, I_*beta/(4*omega0) + Rational(9,4), I_*beta/(4*omega0) - Rational(1,4), exp(2*I_*omega0*tau))",
         "G(1, b; c; z) read as 2F1(1, b; c; z)"),
    _def("C11(0)", r"C_{11}(0) = \frac{(\beta^2 - \omega_0^2)}{2\omega_0^3} + \frac{3(1 - i)\lambda\sqrt{\pi}(\beta^2"
                   r" + 10\omega_0^2)\Gamma\left(\frac{i\beta}{4\omega_0} - \frac{5}{4}\right)}{256\omega_0^3\Gamma\left("
                   r"\frac{i\beta}{4\omega_0} + \frac{9}{4}\right)}",
         "(beta**2 - omega0**2)/(2*omega0**3) + 3*(1 - I_)*lam*sqrt(pi)*(beta**2 + 10*omega0**2)"
         "*gamma(I_*beta/(4*omega0) - Rational(5,4))/(256*omega0**3*gamma(I_*beta/(4*omega0) + Rational(9,4)))"),
    _def("C12(0)", r"C_{12}(0) = \frac{\beta}{\omega_0^2}", "beta/omega0**2"),
    _def("C11^d", r"C_{11}^d(\tau) = -\frac{\cos^2(\omega_0 \tau)}{2\omega_0} - \frac{2}{5\omega_0}"
                  r" \left(\frac{\sin(\omega_0 \tau)}{\omega_0}\right)^{\frac{3}{5}}",
         "-cos(omega0*tau)**2/(2*omega0) - 2/(5*omega0)*(sin(omega0*tau)/omega0)**Rational(3,5)"),
    _def("C12^d", r"C_{12}^d(\tau) = \frac{\sin(2\omega_0 \tau) - 2\omega_0 \tau}{4\omega_0} - \frac{4}{5}"
                  r" e^{i\omega_0 \tau} G\left(1, \frac{9}{4}, -\frac{1}{4}, e^{2i\omega_0 \tau}\right)"
                  r" \left(\frac{\sin(\omega_0 \tau)}{\omega_0}\right)^{\frac{7}{5}}",
         "(sin(2*omega0*tau) - 2*omega0*tau)/(4*omega0) - Rational(4,5)*exp(I_*omega0*tau)"
         "*G(1, Rational(9,4), -Rational(1,4), exp(2*I_*omega0*tau))*(sin(omega0*tau)/omega0)**Rational(7,5)",
         "G(1, 9/4, -1/4, z) read as 2F1(1, 9/4; -1/4; z)"),
    _def("omega0(0)", r"\omega_0 = \left(\frac{5}{4}\right)^{\frac{1}{10}} \approx 1.023",
         "Rational(5,4)**Rational(1,10)", "omega0 at lambda = 0 (Sec. 3.2)"),
    # Numeric claims of the text
    _claim("tau_Hertz", r"the dimensionless Hertz's contact duration ... by substituting Eq. (9) to Eq. (2):"
                        r" $\tau_{\text{Hertz}} \approx 3.214$",
           '3.214', 'tau_Hertz'),
    _claim("tau_d0", r"For $\lambda = 0$, we can calculate that $\tau_d \approx 3.072$",
           '3.072', 'tau_d at lambda = 0'),
    _claim("omega0_lam0", r"$\omega_0 = \left(\frac{5}{4}\right)^{\frac{1}{10}} \approx 1.023$",
           '1.023', 'omega0 at lambda = 0'),
    _claim("lambda_bound", r"Simplifying Inequation (81) reveals that Eq. (80) can be used for"
                           r" $\lambda \in [0, 2.442)$",
           '2.442', 'upper end of lambda for (80)'),
    _claim("eq24_5pct", r"For $\lambda \in [0, 100]$ ... Eq. (24) can be used for the estimation of"
                        r" $\bar{\delta}_m^{-\frac{3}{2}}$, with a maximum error less than 5%",
           '0.05, 100', 'max rel. error of (24), lambda range end'),
    _claim("Fm_ham1_2.90pct", r"the present first-order solution can predict the maximum contact force with a"
                              r" relative error less than 2.90%",
           '0.0290', 'max rel. error'),
    _claim("Fm_ham0_5.11pct", r"The present zeroth-order solution can provide an estimation of $\bar{F}_m$ with"
                              r" relative error less than 5.11%, but only for the case of $\lambda > 1.5$",
           '0.0511, 1.5', 'max rel. error, lower end of lambda'),
    _claim("impulse_ham1_3.95pct", r"the relative error of the present first-order solution is less than 3.95%",
           '0.0395', 'max rel. error'),
    _claim("eq70_10pct_1pct", r"the relative error of Eq. (70) is less than 10% for most of the cases and less"
                              r" than 1% for $\lambda \geq 1.61$",
           '0.10, 0.01, 1.61', 'rel. error mostly, rel. error above, lambda from'),
    _claim("eq80_to_1.8", r"the present model Eq. (80) derived from the zeroth-order solution extends the"
                          r" applicable region to $\lambda \leq 1.8$",
           '1.8', 'upper end of lambda'),
    _claim("int_F2_poly", r"$\int_0^{\tau_d} \bar{F}^2 d\tau \approx 1.78 - 2.79\lambda + 2.36\lambda^2 + \dots$",
           '1.78, -2.79, 2.36', 'polynomial coefficients'),
    _claim("fit55", r"$\tau_d = \tau_{\text{Hertz}} \exp(0.23\lambda^{1.80})$ (fit of the first-order results)",
           '3.214, 0.23, 1.80', 'tau_Hertz, factor, power'),
    _claim("xi_V0^0.2", r"for small $\lambda$, we find that the Zener loss is proportional to $V_0^{0.2}$",
           '0.2', 'power of V0'),
    _claim("table1_lambda_range", r"Table 1 ($R$ = 0.9 mm; sphere $E$ = 12.23 GPa, $\nu$ = 0.21, $\rho$ ="
                                  r" 879 kg/m$^3$; plate $E$ = 73 GPa, $\nu$ = 0.21, $\rho$ = 2500 kg/m$^3$),"
                                  r" $V_0$ from 1 to 20 m/s, $H$ from 0.18 to 0.75 mm 'to enable a wide range"
                                  r" of $\lambda$' (Fig. 5 and the text use $\lambda$ from about 0.07 to 2.3)",
           '0.07, 2.3', 'lambda range'),
    _claim("mueller_linear", r"Mueller's model always underestimates $\bar{F}_m$, with the relative error up"
                             r" to 38.72% ... [the impulse] is compared with Mueller's solution, showing a"
                             r" relative error between 12.60% and 52.63%",
           '0.3872, 0.1260, 0.5263', 'max F_m rel. error, impulse rel. error from, to'),
    _claim("hunter_reed_k", r"Using the material properties in the present FEM simulation, we calculated"
                            r" Hunter's coefficient is $k_{\text{Hunter}} \approx 0.0013$ and Reed's"
                            r" coefficient is $k_{\text{Reed}} \approx 0.0058$ [$\xi = k V_0^{0.6}$ for"
                            r" a sphere on a half-space, $V_0$ in m/s]",
           '0.0013, 0.0058', 'k_Hunter, k_Reed'),
)


class Table1(TypedDict):
    """Table 1 of the appendix: the sphere's (1) and the plate's (2) materials, the sphere's radius
    and the appendix's ranges of impact speed and plate thickness, in SI units."""

    R: float
    E1: float
    nu1: float
    rho1: float
    E2: float
    nu2: float
    rho2: float
    V0_range: tuple[float, float]
    H_range: tuple[float, float]


#: Table 1 of the appendix (FEM materials) and the appendix's ranges, as printed, in SI units.
TABLE1: Table1 = {"R": 0.9e-3, "E1": 12.23e9, "nu1": 0.21, "rho1": 879.0, "E2": 73e9, "nu2": 0.21,
                  "rho2": 2500.0, "V0_range": (1.0, 20.0), "H_range": (0.18e-3, 0.75e-3)}


def by_id(item_id: str) -> Printed:
    """The printed item with this id; ValueError listing nothing else if absent."""
    for it in ITEMS:
        if it.id == item_id:
            return it
    raise ValueError(f"no printed item with id {item_id!r}")


def numbers(item: Printed) -> list[str]:
    """The printed numbers of a claim, as strings with their printed digits."""
    return [n.strip() for n in (item.parse or "").split(",") if n.strip()]


def parse(item: Printed, evaluate: bool = True) -> Expr | list[str] | None:
    """The SymPy form of the printed transcription (None when there is none).

    ``evaluate=False`` keeps the printed structure for display (``(5/4)^{-3/2}`` stays a power).
    """
    if item.parse is None:
        return None
    if item.kind == "claim":
        return numbers(item)
    ns = dict(NS, gamma=sp.gamma)
    ns["I_"] = sp.I
    return sp.sympify(item.parse, locals=ns, rational=False, evaluate=evaluate)
