"""Sweeps of runs, their execution and their aggregation over seeds."""
