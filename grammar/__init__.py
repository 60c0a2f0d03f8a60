"""The bcc expression language: `expressions.lark`, shipped as package data."""
from pathlib import Path

GRAMMAR_FILE = Path(__file__).with_name("expressions.lark")
