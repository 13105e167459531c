"""Scenario batches: many isolated runs, on Ray (issue 36). docs/BATCH.md."""
