# Sphinx configuration of mjbuoy's documentation site. Pages are Markdown
# (MyST). Build: cmake --build build --target docs (or
# python3 -m sphinx -W --keep-going -n -b html docs build/docs/html).
project = "mjbuoy"
author = "the mjbuoy authors"
copyright = "the mjbuoy authors"

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
master_doc = "index"
exclude_patterns = ["_build", "README.md"]

# anchors for headings down to ####, so [text](page.md#a-heading) resolves
# and a missing anchor is a warning (an error with -W)
myst_heading_anchors = 4
myst_enable_extensions = []

html_theme = "sphinx_rtd_theme"
html_title = "mjbuoy"
html_show_sourcelink = False
html_theme_options = {"navigation_depth": 3}
