"""The exact solution of Zener's equation (10): direct integration and its fast tables.

- :mod:`.phases`: the driver of the scipy path's three phases, each reading of the contact given
  as data (its forms and events);
- :mod:`.solver`: scipy integration with analytic phases in u = sqrt(delta) at both ends of the
  contact (the reference in float64);
- :mod:`.mp`: the same problem in mpmath at any precision (the independent reference);
- :mod:`.table`: Chebyshev tables of the solution, evaluated in numpy (the default path);
- :mod:`.table_layout`: the constants of the tables' time maps, written into the generated table
  by the builder and read back from it by ``table`` (the pieces are the engine's description);
- :mod:`.table_fields`: what both exact tables derive from their stored series (summary fields,
  derivatives with the e/xi switch, the inverses' log quantities);
- :mod:`.table_build`: builds those tables offline into ``generated/exact_table.py``.
"""
