"""One run: running icedem, reading what it writes, sweep files, the guard of every output."""
