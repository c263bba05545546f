"""The study's report: figures, plotting helpers, tables and the landing page."""
