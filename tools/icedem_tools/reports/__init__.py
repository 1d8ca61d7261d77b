"""A sweep's report beside the seed paper: its sections, tables, figures, pictures and movies."""
