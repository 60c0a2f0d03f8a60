"""`python -m bcc` is the `bcc` command."""
from .cli import main

main()
