"""Paper audit: each printed item of the paper against the derivation and the exact solution."""
