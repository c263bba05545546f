"""One entry point per Snakemake rule, in a module named after the rule, each with a ``run(...)``
function: it reads the rule's inputs, calls the layers below (runs, analysis, claims, report) and writes
the rule's outputs; the rule's script (``workflow/scripts/<rule>.py``) only passes it the paths.
The top layer of :mod:`roughcontact.study` but the registries (``tests/test_layers.py``)."""
