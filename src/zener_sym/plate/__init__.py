"""The sphere on a bounded plate: Kirchhoff plate modes and the impact with every sub-impact.

Zener's equation (10) assumes an infinite plate. On a bounded plate the flexural wave comes back
from the edge; here the plate is a sum of its modes plus the static correction for the modes left
out (:mod:`.modal`), and the impact is solved contact by contact to its proved end.
"""
