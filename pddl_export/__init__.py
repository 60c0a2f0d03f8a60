"""PDDL out: a compiled Model written as an exact grounded STRIPS task (task, domains,
symbolic, writer), and a bcc plan as the export's operators, checked by a validator
(plans). The back end's other way out, beside the generated successor code."""
