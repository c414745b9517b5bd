"""The toolkit version and the spec revision this package was generated from."""

__version__ = '0.2.0'
SPEC_REVISION = '300071 rev 03'
