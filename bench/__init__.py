"""Benchmarks of the CBF toolkit (make bench)."""
