"""cbfgen: every CBF binding generated from spec/cbf.yaml."""

# The toolkit's version: the one place it is written. pyproject.toml reads it, and
# every binding carries it (cbf.__version__, CBF_TOOLKIT_VERSION, the docs pages).
__version__ = "0.2.0"
# SPDX identifier of the toolkit and of what it generates (pyproject.toml says the same; a test checks).
__license__ = "Apache-2.0"  # the code's licence (LICENSE; README "Licences"); spec content: meta.license
