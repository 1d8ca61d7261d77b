"""Parameter sweeps of icedem runs (issue 5): description, expansion, execution."""
