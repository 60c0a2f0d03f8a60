"""The HDDL front end: IPC HTN domain and problem files -> `HtnProblem` (hddl/read.py),
the IPC plan format with its decomposition tree (hddl/plan.py) and a verifier of plans in
it (hddl/verify.py). Its command, `bcc import hddl`, is cli/hddl.py."""
