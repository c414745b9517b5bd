"""The conformance runner: one oracle (the golden cases), a thin testee per
binding, and this runner, which owns the verdict. See conformance/README.md."""
