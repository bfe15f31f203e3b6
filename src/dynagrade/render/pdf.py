"""PDFs from typst sources, compiled in-process with typst's own fonts only (the same PDF
on every machine; no package downloads).

Usage::

    compiler = PdfCompiler()                       # one per run and process
    pdf = compiler.compile(preamble + body)        # bytes
    pdf = compile_pdf(source)                      # once, without keeping a compiler
    pdf = compiler.compile(sheet, standards=ACCESSIBLE)   # PDF/UA-1, checked by typst

Every PDF is tagged (typst's default: headings, paragraphs, tables, figures with their
alternative text, the document language from ``set text(lang: ...)``); with
``standards=ACCESSIBLE`` typst also checks PDF/UA-1 and refuses a document that breaks it
(an image or an equation without alternative text, a missing title).

A compiler keeps one typst compiler per root folder: it holds the loaded fonts and
typst's caches, which makes later documents about twice as fast. It belongs to whoever
runs the work (an exam generation), never to the module.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Callable

_PAGE = re.compile(rb"/Type\s*/Page\b")
ACCESSIBLE = ("ua-1",)


class PdfCompiler:
    """typst compilers by root folder, created on first use."""

    def __init__(self):
        self._compilers: dict[str, object] = {}

    def compile(self, source: str, root: str | None = None,
                standards: tuple[str, ...] = ()) -> bytes:
        """The PDF of the typst document ``source``; images resolve under ``root``;
        ``standards`` are PDF standards typst checks and declares (see :data:`ACCESSIBLE`)."""
        import typst

        key = root or ""
        if key not in self._compilers:
            self._compilers[key] = typst.Compiler(root=root, ignore_system_fonts=True)
        return self._compilers[key].compile(input=source.encode("utf-8"),
                                            pdf_standards=list(standards))

    def __getstate__(self):  # a worker process starts with no compilers of its own
        return {"_compilers": {}}


def compile_pdf(source: str, root: str | None = None,
                standards: tuple[str, ...] = ()) -> bytes:
    """The PDF of ``source`` with a compiler used once (see :class:`PdfCompiler`)."""
    return PdfCompiler().compile(source, root, standards)


def page_count(pdf: bytes) -> int:
    """The number of pages of a PDF, read from its page objects (0 when none are found)."""
    return len(_PAGE.findall(pdf))


def embedded_pages_source(root: Path, pdfs: list[str], fallback: Callable[[], str]) -> str:
    """A typst source that puts the PDFs ``pdfs`` (paths relative to ``root``) one after
    another, page by page, as embedded vector pages (no second layout). ``fallback()``
    gives the source to use when a page count cannot be read."""
    lines = ['#set page(paper: "a4", margin: 0pt, header: none, numbering: none)']
    for relative in pdfs:
        pages = page_count((root / relative).read_bytes())
        if pages == 0:
            return fallback()
        for page in range(1, pages + 1):
            lines.append(f'#page(image("/{relative}", page: {page}, width: 100%))')
    return "\n".join(lines) + "\n"
