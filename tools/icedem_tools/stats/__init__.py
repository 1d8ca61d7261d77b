"""The statistics the verdicts are made with."""
