"""The studies and validations: each runs its sweep file and writes its page."""
