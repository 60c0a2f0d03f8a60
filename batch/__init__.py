"""`bcc batch`: sweeps of solves over dungeons x solvers x seeds, on a process pool or Ray (issue 12)."""
