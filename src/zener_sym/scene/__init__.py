"""Physical scenes: a sphere, a plate and a speed in SI units, and which model to use for them.

- :mod:`.scene`: :class:`~.scene.Scene` and its dimensional result;
- :mod:`.materials`, :mod:`.units`: material presets and unit parsing;
- :mod:`.scaling`: dimensionless <-> SI (Eqs. 8, 9, 57-81);
- :mod:`.checks`: validity checks of the assumptions (warnings);
- :mod:`.stress_waves`: Hunter's and Reed's half-space stress-wave loss (Fig. 14);
- :mod:`.envelopes`, :mod:`.select`: measured error envelopes and the model selection on them.
"""
