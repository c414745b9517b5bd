"""Reliability campaign (issue #7): corruption detection, blind spots, differential testing."""
