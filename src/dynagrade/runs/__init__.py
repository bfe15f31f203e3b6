"""The machinery every long run shares: files written atomically, output folders that
hold exactly one complete run, worker processes, and caches keyed by an exercise's
content."""
