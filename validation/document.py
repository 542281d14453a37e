"""A report as a list of blocks, written as Markdown and as self-contained HTML alike.

Blocks: ``("h", level, text)``, ``("p", text)``, ``("list", items)``,
``("table", header, rows)``, ``("image", file, caption)`` (a file beside the
report, referenced relatively), ``("code", text)``. Both writers get the same
blocks, so the two files hold the same content.
"""

from __future__ import annotations

import html

__all__ = ["markdown", "html_page"]

_CSS = """body{font-family:system-ui,sans-serif;max-width:78em;margin:2em auto;padding:0 1em;line-height:1.45}
table{border-collapse:collapse;margin:1em 0;font-size:90%}td,th{border:1px solid #bbb;padding:.25em .5em;
text-align:left}th{background:#eee}img{max-width:100%;border:1px solid #ddd}figure{margin:1.5em 0}
figcaption{font-size:90%;color:#444}.pass{color:#186a18;font-weight:bold}.fail{color:#b00;font-weight:bold}
.info{color:#666}.agrees{color:#186a18}.disagrees{color:#a55a00;font-weight:bold}pre{background:#f6f6f6;
padding:.5em;overflow-x:auto}td.num{white-space:nowrap;text-align:right;font-variant-numeric:tabular-nums}"""
_VERDICTS = ("pass", "fail", "info", "agrees", "disagrees")


def _cell_md(value) -> str:
    return str(value).replace("|", "\\|").replace("\n", " ")


def markdown(blocks) -> str:
    """The blocks as GitHub-flavoured Markdown."""
    out = []
    for block in blocks:
        kind = block[0]
        if kind == "h":
            out.append(f"{'#' * block[1]} {block[2]}")
        elif kind == "p":
            out.append(block[1])
        elif kind == "list":
            out.append("\n".join(f"- {item}" for item in block[1]))
        elif kind == "table":
            header, rows = block[1], block[2]
            lines = ["| " + " | ".join(map(_cell_md, header)) + " |", "|" + "---|" * len(header)]
            lines += ["| " + " | ".join(map(_cell_md, row)) + " |" for row in rows]
            out.append("\n".join(lines))
        elif kind == "image":
            out.append(f"![{block[2]}]({block[1]})\n\n*{block[2]}*")
        elif kind == "code":
            out.append(f"```\n{block[1]}\n```")
        else:
            raise ValueError(f"unknown block {kind!r}")
    return "\n\n".join(out) + "\n"


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _cell_html(value) -> str:
    """A table cell: verdicts coloured, numbers kept on one line (an exponent never wraps) and right-aligned."""
    text = html.escape(str(value))
    if text in _VERDICTS:
        return f'<td><span class="{text}">{text}</span></td>'
    return f'<td class="num">{text}</td>' if _is_number(text) else f"<td>{text}</td>"


def html_page(title: str, blocks) -> str:
    """The blocks as one HTML page (inline CSS, images by relative path: opens without a server)."""
    out = [f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>",
           f"<style>{_CSS}</style></head><body>"]
    for block in blocks:
        kind = block[0]
        if kind == "h":
            out.append(f"<h{block[1]}>{html.escape(block[2])}</h{block[1]}>")
        elif kind == "p":
            out.append(f"<p>{html.escape(block[1])}</p>")
        elif kind == "list":
            out.append("<ul>" + "".join(f"<li>{html.escape(str(i))}</li>" for i in block[1]) + "</ul>")
        elif kind == "table":
            head = "".join(f"<th>{html.escape(str(h))}</th>" for h in block[1])
            body = "".join("<tr>" + "".join(_cell_html(v) for v in row) + "</tr>" for row in block[2])
            out.append(f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>")
        elif kind == "image":
            src, caption = html.escape(block[1], quote=True), html.escape(block[2])
            out.append(f'<figure><img src="{src}" alt="{caption}"><figcaption>{caption}</figcaption></figure>')
        elif kind == "code":
            out.append(f"<pre>{html.escape(block[1])}</pre>")
        else:
            raise ValueError(f"unknown block {kind!r}")
    out.append("</body></html>\n")
    return "\n".join(out)
