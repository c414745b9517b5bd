"""One subpackage per target; each exposes emit(spec) -> {relative path: bytes}."""
