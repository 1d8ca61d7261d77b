"""Floe layouts from top-view photos, and their validation on synthetic photos."""
