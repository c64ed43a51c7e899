"""rollertools: maintenance commands, `PYTHONPATH=scripts python3 -m rollertools.NAME`:

- merge_sweep: the parts of a sweep run as a job array merged into one CSV (jobs/slurm, docs/squeal.md 6.2);
- options_table: docs/options.md from `roller -help` (runs at import: a command only).
"""
__all__ = ["merge_sweep"]
