"""A report as a list of blocks, written as Markdown and as self-contained HTML alike.

Blocks: ``("h", level, text)``, ``("p", text)``, ``("list", items)``,
``("table", header, rows)``, ``("image", file, caption)`` (a file beside the
report, referenced relatively), ``("code", text)``, ``("toc",)`` (a table of
contents linking every heading of level 2 and 3), ``("details", summary,
blocks)`` (blocks folded under a one-line summary, HTML ``<details>``),
``("link", html_file, md_file, text)`` (a paragraph linking another page of
the report, which is written in both formats: the Markdown links ``md_file``,
the HTML ``html_file``). Both
writers get the same blocks, so the two files hold the same content. Every
heading gets an anchor (``anchors``): GitHub's for the Markdown, the same as
an ``id`` in the HTML.
"""

from __future__ import annotations

import html
import re

__all__ = ["anchors", "html_page", "markdown"]

_CSS = """body{font-family:system-ui,sans-serif;max-width:78em;margin:2em auto;padding:0 1em;line-height:1.45}
table{border-collapse:collapse;margin:1em 0;font-size:90%}td,th{border:1px solid #bbb;padding:.25em .5em;
text-align:left}th{background:#eee}img{max-width:100%;border:1px solid #ddd}figure{margin:1.5em 0}
figcaption{font-size:90%;color:#444}.pass{color:#186a18;font-weight:bold}.fail{color:#b00;font-weight:bold}
.info{color:#666}.agrees{color:#186a18}.disagrees{color:#a55a00;font-weight:bold}pre{background:#f6f6f6;
padding:.5em;overflow-x:auto}td.num{white-space:nowrap;text-align:right;font-variant-numeric:tabular-nums}
ul.toc{columns:2;list-style:none;padding-left:0}li.toc3{padding-left:1.5em;font-size:90%}
summary{cursor:pointer;font-weight:bold;margin:.5em 0}"""
_VERDICTS = ("pass", "fail", "info", "agrees", "disagrees")


def _cell_md(value) -> str:
    return str(value).replace("|", "\\|").replace("\n", " ")


def _headings(blocks):
    """Every heading block, folded ones included, in order."""
    for block in blocks:
        if block[0] == "h":
            yield block
        elif block[0] == "details":
            yield from _headings(block[2])


def anchors(blocks) -> dict:
    """Heading block's position among the headings -> its anchor, as GitHub makes it: lower case, only
    letters, digits, spaces, '-' and '_' kept, spaces as '-', a repeat suffixed -1, -2, ..."""
    out: dict[int, str] = {}
    seen: dict[str, int] = {}
    for k, (_, _, text) in enumerate(_headings(blocks)):
        slug = re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        out[k] = f"{slug}-{n}" if n else slug
    return out


def _toc(blocks) -> list:
    """(level, text, anchor) of every heading of level 2 and 3."""
    ids = anchors(blocks)
    return [(level, text, ids[k]) for k, (_, level, text) in enumerate(_headings(blocks)) if level in (2, 3)]


def markdown(blocks) -> str:
    """The blocks as GitHub-flavoured Markdown."""
    return "\n\n".join(_markdown(blocks, blocks)) + "\n"


def _markdown(blocks, page) -> list:
    out = []
    for block in blocks:
        kind = block[0]
        if kind == "h":
            out.append(f"{'#' * block[1]} {block[2]}")
        elif kind == "toc":
            out.append("\n".join(f"{'  ' * (level - 2)}- [{text}](#{anchor})" for level, text, anchor in _toc(page)))
        elif kind == "details":
            out.append(f"<details><summary>{html.escape(block[1])}</summary>\n\n"
                       + "\n\n".join(_markdown(block[2], page)) + "\n\n</details>")
        elif kind == "p":
            out.append(block[1])
        elif kind == "link":
            out.append(f"[{block[3]}]({block[2]})")
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
    return out


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
    out += _html(blocks, blocks, iter(anchors(blocks).values()))
    out.append("</body></html>\n")
    return "\n".join(out)


def _html(blocks, page, ids) -> list:
    """The blocks as HTML elements; ``ids`` yields the headings' anchors in order."""
    out = []
    for block in blocks:
        kind = block[0]
        if kind == "h":
            out.append(f'<h{block[1]} id="{next(ids)}">{html.escape(block[2])}</h{block[1]}>')
        elif kind == "toc":
            items = "".join(f'<li class="toc{level}"><a href="#{anchor}">{html.escape(text)}</a></li>'
                            for level, text, anchor in _toc(page))
            out.append(f'<nav><strong>Contents</strong><ul class="toc">{items}</ul></nav>')
        elif kind == "details":
            out.append(f"<details><summary>{html.escape(block[1])}</summary>")
            out += _html(block[2], page, ids)
            out.append("</details>")
        elif kind == "p":
            out.append(f"<p>{html.escape(block[1])}</p>")
        elif kind == "link":
            out.append(f'<p><a href="{html.escape(block[1], quote=True)}">{html.escape(block[3])}</a></p>')
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
    return out
