"""``zener-sym report``, the main job: one markdown section per part of the project.

- :mod:`.build`: the sections and the runner;
- :mod:`.format`: number and table formatting;
- :mod:`.exact_fast`, :mod:`.ham_envelopes`: the longer sections.
"""
