/*
 * dem_wall.c: a DEM-style explicit time stepper (velocity Verlet, fixed time step) of a sphere
 * hitting a rigid wall with the viscoelastic Hertz force (Kuwabara & Kono 1987; Brilliantov
 * et al. 1996), in SI units. It measures the coefficient of restitution e and the contact time
 * from its own trajectory and prints them beside zs_summary's, which reads them off the exact
 * tables of Zener's equation (10) through the scaling
 *
 *     T = (m / rho)^{2/5} v0^{-1/5},  xi = v0 T delta(t / T),  lambda = A / T,
 *
 * with rho = (4/3) E* sqrt(R), 1/E* = (1 - nu^2)/E (rigid wall) and A the material's dissipative
 * time (zener_sym.scene.grains, derived in derivation/viscoelastic.py).
 *
 * Build:  cc -std=c99 -O2 -I ../../generated/c dem_wall.c ../../generated/c/zener_sym.c -lm
 * Run:    ./a.out [steps_per_T] [delta|force]
 *         steps_per_T: time steps per contact time scale T (default 200)
 *         delta: the contact ends at xi = 0 (Zener's plate, ZS_DELTA, default);
 *         force: at the force's zero (the grain reading, ZS_FORCE; the force is never attractive).
 * Output: one line "dt e_stepper e_zs rel_err_e t_contact_stepper t_contact_zs rel_err_t".
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zener_sym.h"

/* a steel sphere (radius 5 mm) on a rigid wall at 1 m/s */
static const double R = 5e-3;         /* m */
static const double E = 200e9;        /* Pa */
static const double NU = 0.3;
static const double DENSITY = 7850.0; /* kg/m^3 */
static const double A = 4e-6;         /* s, dissipative time of the material */
static const double V0 = 1.0;         /* m/s, impact speed */

/* G = xi^{3/2}: the elastic force is rho G, the dissipative one rho A dG/dt */
static double G(double xi)
{
    return xi > 0.0 ? xi * sqrt(xi) : 0.0;
}

int main(int argc, char **argv)
{
    const double pi = 3.14159265358979323846;
    double steps = argc > 1 ? atof(argv[1]) : 200.0;
    int grain = argc > 2 && strcmp(argv[2], "force") == 0;
    double m = DENSITY * 4.0 / 3.0 * pi * R * R * R;
    double rho = 4.0 / 3.0 * (E / (1.0 - NU * NU)) * sqrt(R);
    double T = pow(m / rho, 0.4) * pow(V0, -0.2);
    double lam = A / T, dt = T / steps;
    double xi = 0.0, v = V0, t = 0.0; /* compression and its rate (relative velocity) */
    double t_end = -1.0, v_end = 0.0, k = 0.0;
    zs_summary_t s;
    if (!(steps >= 10.0)) {
        fprintf(stderr, "dem_wall: steps_per_T must be a number >= 10\n");
        return 2;
    }
    if (zs_summary(lam, grain ? ZS_FORCE : ZS_DELTA, &s) != ZS_OK) {
        fprintf(stderr, "dem_wall: zs_summary has no result for lambda = %g, contact end %s\n",
                lam, grain ? "force" : "delta");
        return 2;
    }
    k = rho / m;
    /* Velocity Verlet. The dissipative force rho A dG/dt is a time derivative, so its impulse
       over a step is taken exactly, -rho A (G_{n+1} - G_n); the elastic one by the trapezoid
       of the usual half kicks. (With the dissipative force's value at the step ends instead,
       its sqrt(xi) onset at the impact makes the stepper O(dt^1.5).) */
    while (t < 10.0 * T) {
        double g0 = G(xi), a0 = -k * (g0 + A * 1.5 * sqrt(xi > 0.0 ? xi : 0.0) * v);
        double xi1 = xi + dt * v + 0.5 * dt * dt * a0, g1 = G(xi1);
        double v1 = v - 0.5 * dt * k * (g0 + g1) - k * A * (g1 - g0);
        if (!grain && xi1 <= 0.0 && xi > 0.0) {
            /* left the wall within the step: the crossing from the step's own position
               polynomial xi + v s + a0 s^2 / 2 = 0, the velocity there by the same impulse rule
               over the fraction w of the step */
            double disc = v * v - 2.0 * a0 * xi;
            double w = 2.0 * xi / (-v + sqrt(disc > 0.0 ? disc : 0.0)) / dt;
            t_end = t + w * dt;
            v_end = v - 0.5 * w * dt * k * g0 + k * A * g0;
            break;
        }
        if (grain && t > 0.0) {
            double f0 = g0 + A * 1.5 * sqrt(xi) * v, f1 = g1 + A * 1.5 * sqrt(xi1) * v1;
            if (f1 <= 0.0) { /* the force's zero within the step: the grain leaves there */
                double w = f0 / (f0 - f1);
                t_end = t + w * dt;
                v_end = v + w * (v1 - v);
                break;
            }
        }
        xi = xi1;
        v = v1;
        t += dt;
    }
    if (t_end < 0.0) {
        fprintf(stderr, "dem_wall: no end of contact within 10 T\n");
        return 1;
    }
    {
        double e = -v_end / V0, tc = s.tau_d * T;
        printf("lambda %.6f T %.6e s\n", lam, T);
        printf("%.6e %.15f %.15f %.3e %.12e %.12e %.3e\n", dt, e, s.e, fabs(e - s.e) / s.e,
               t_end, tc, fabs(t_end - tc) / tc);
    }
    return 0;
}
