"""The user guide's generated pages: the case files' keys, the command line, the reported keys.

Written when the docs build, from the code that reads the case files, parses the command line and writes
the results, so that the guide cannot drift from what pocket does.
"""


def setup(app):
    """Register the generator with Sphinx."""
    return {"parallel_read_safe": True, "parallel_write_safe": True}
