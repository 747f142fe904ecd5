"""Analysis of cellsim results: the experiment matrix, tidy tables, figures, claims and the report."""
