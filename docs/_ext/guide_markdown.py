"""Markdown for the generated pages: tables whose cells cannot break the table or start markup."""

from __future__ import annotations

import re

#: a code span, and a command-line flag in running text (``--law``), which typography would turn into an en dash
_CODE = re.compile(r"(`[^`]*`)")
_FLAG = re.compile(r"(?<![\w`-])(--[A-Za-z][\w-]*)")

#: a generated file's first line: what wrote it, so that no one edits it by hand
HEADER = "<!-- written by docs/_ext/pocket_guide.py from pocket's code when the docs build: do not edit -->\n\n"


def code(text) -> str:
    """``text`` as inline code (empty text as an em dash)."""
    text = str(text)
    if not text:
        return "—"
    ticks = "``" if "`" in text else "`"
    return f"{ticks}{text}{ticks}" if ticks == "`" else f"{ticks} {text} {ticks}"


def cell(text) -> str:
    """``text`` as one table cell (or a paragraph): on one line, its pipes escaped, and outside its code spans
    its asterisks, brackets and angle brackets literal and its flags made code."""
    out = []
    for i, part in enumerate(_CODE.split(" ".join(str(text).split()))):
        if i % 2:  # a code span: only a pipe would end the table's cell
            out.append(part.replace("|", "\\|"))
            continue
        for char in ("\\", "|", "*", "<", ">", "[", "]"):
            part = part.replace(char, "\\" + char)
        out.append(_FLAG.sub(r"`\1`", part))
    return "".join(out)


def table(header: tuple[str, ...], rows) -> str:
    """A Markdown table; ``rows`` hold Markdown already made safe (``cell``, ``code``)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines) + "\n"
