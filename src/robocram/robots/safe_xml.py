"""A small, safe XML reader for URDF: no DOCTYPE, no entities, line numbers kept.

URDFs come from many places; a DOCTYPE with ENTITY declarations can expand without bound
("billion laughs") or pull in external files. URDF needs neither, so both are refused.
"""

from __future__ import annotations

import codecs
import re
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from robocram.robots.errors import UrdfError


@dataclass
class XmlNode:
    """One XML element with its attributes, children, text and the line it starts on."""

    tag: str
    attrib: dict[str, str]
    line: int
    children: list[XmlNode] = field(default_factory=list)
    text: str = ""  # the character data directly inside the element

    def find(self, tag: str) -> XmlNode | None:
        """First child with this tag, or ``None``."""
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[XmlNode]:
        """All children with this tag, in document order."""
        return [c for c in self.children if c.tag == tag]


class _Builder:
    """Builds the node tree from expat callbacks and refuses DTDs."""

    def __init__(self, parser: expat.XMLParserType, source: str | Path) -> None:
        self.parser = parser
        self.source = source
        self.stack: list[XmlNode] = []
        self.root: XmlNode | None = None

    def start(self, tag: str, attrib: dict[str, str]) -> None:
        node = XmlNode(tag, dict(attrib), self.parser.CurrentLineNumber)
        if self.stack:
            self.stack[-1].children.append(node)
        else:
            self.root = node
        self.stack.append(node)

    def end(self, tag: str) -> None:
        self.stack.pop()

    def chars(self, data: str) -> None:
        if self.stack:
            self.stack[-1].text += data

    def refuse_dtd(self, *args: object) -> int:
        raise UrdfError(
            self.source,
            "DOCTYPE/ENTITY declarations are refused (unsafe XML); remove the DOCTYPE",
            self.parser.CurrentLineNumber,
        )


_DECLARED_ENCODING = re.compile(rb"""^<\?xml[^>]*?encoding\s*=\s*["']([A-Za-z0-9._-]+)["']""")


def decode_xml(data: bytes, source: str | Path) -> str:
    """Text of an XML file in the encoding its declaration (or BOM) names, else UTF-8."""
    if data.startswith(codecs.BOM_UTF8):
        encoding, data = "utf-8", data[len(codecs.BOM_UTF8) :]
    elif data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        encoding = "utf-16"
    else:
        declared = _DECLARED_ENCODING.match(data.lstrip())
        encoding = declared.group(1).decode("ascii") if declared else "utf-8"
    try:
        return data.decode(encoding)
    except LookupError as err:
        raise UrdfError(source, f"unknown encoding {encoding!r} in the XML declaration", 1) from err
    except UnicodeDecodeError as err:
        line = data.count(b"\n", 0, err.start) + 1
        raise UrdfError(
            source,
            f"byte {data[err.start]:#04x} is not {encoding}; declare the file's encoding "
            f'(<?xml version="1.0" encoding="...">) or save it as UTF-8',
            line,
        ) from err


def parse_xml(text: str, source: str | Path) -> XmlNode:
    """Parse ``text`` into nodes; malformed or unsafe XML raises :class:`UrdfError`."""
    parser = expat.ParserCreate()
    builder = _Builder(parser, source)
    parser.StartElementHandler = builder.start
    parser.EndElementHandler = builder.end
    parser.CharacterDataHandler = builder.chars
    parser.StartDoctypeDeclHandler = builder.refuse_dtd
    parser.EntityDeclHandler = builder.refuse_dtd
    parser.ExternalEntityRefHandler = builder.refuse_dtd
    try:
        parser.Parse(text, True)
    except expat.ExpatError as err:
        message = expat.errors.messages[err.code]
        raise UrdfError(source, f"not well-formed XML: {message}", err.lineno) from err
    if builder.root is None:
        raise UrdfError(source, "no XML element found")
    return builder.root
