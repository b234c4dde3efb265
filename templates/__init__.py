"""Report templates (Jinja2 Markdown per machine and language, and the typst page layout).

This folder is shipped inside the package as ``mechdesign.templates``; edit the files
here, or pass ``--templates DIR`` to use a copy."""
