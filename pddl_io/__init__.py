"""PDDL in: read a domain and problem (read, lifted), ground the reachable part (ground),
compile it into a Model (bits, compile; `bcc import pddl` in importer), keep it lifted for
the lifted search (lifted_states, lifted_joins), and replay a plan on the lifted task
(replay). Writing PDDL out is pddl_export/; the searches that run on an import are in
solvers/ (portfolio, lifted_search, fast_downward)."""
