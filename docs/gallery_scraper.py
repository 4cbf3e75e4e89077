"""The gallery's image scraper: sphinx-gallery's matplotlib scraper with ``bbox_inches="tight"``,
so that legends the package's style puts outside the axes (``legend_outside``) are in the image
(sphinx-gallery's ``image_scrapers`` takes it by its dotted name)."""
from __future__ import annotations

from sphinx_gallery.scrapers import matplotlib_scraper


def tight(block, block_vars, gallery_conf, **kwargs):
    """matplotlib_scraper, saving each figure with its outside legends."""
    return matplotlib_scraper(block, block_vars, gallery_conf, bbox_inches="tight", **kwargs)
