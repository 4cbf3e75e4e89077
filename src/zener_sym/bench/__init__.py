"""Speed against accuracy: work-precision data, charts, a stability map (``zener-sym bench``).

Modules: ``methods`` (the catalogue of methods under test), ``reference`` (the high-precision
reference values), ``timing`` (how time is taken), ``workprecision`` (tables and charts),
``stability`` (where methods fail), ``cmd`` (the command line).
"""
