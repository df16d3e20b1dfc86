#!/usr/bin/env python3
"""Opens the pictures `grape render` wrote and checks that they are what they claim to be.

    check_render.py [--width W --height H] FILE...

PNG: the signature, every chunk's CRC, IHDR first with the given size, IEND last; the image
data inflated and unfiltered (zlib, standard library only), and not every pixel the same.
SVG: well-formed XML whose root is <svg> (of the given width and height), drawing something
(an element other than a background <rect>, a <g> or <defs>).
PDF: starts with %PDF- and ends with %%EOF, a page of the given MediaBox, and a content
stream that draws (inflated: more path operators than a background rectangle needs).
Exit status 0 when every file passes, 1 (saying why) otherwise.
"""
import argparse
import re
import struct
import sys
import xml.etree.ElementTree as ET
import zlib


class Bad(Exception):
    pass


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def check_png(data, width, height):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise Bad("no PNG signature")
    at, chunks = 8, []
    while at < len(data):
        if at + 12 > len(data):
            raise Bad(f"truncated chunk at byte {at}")
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        if len(body) != length or at + 12 + length > len(data):
            raise Bad(f"truncated {kind!r} chunk")
        (crc,) = struct.unpack(">I", data[at + 8 + length:at + 12 + length])
        if zlib.crc32(kind + body) != crc:
            raise Bad(f"bad CRC in the {kind!r} chunk")
        chunks.append((kind, body))
        at += 12 + length
    if not chunks or chunks[0][0] != b"IHDR" or len(chunks[0][1]) != 13:
        raise Bad("IHDR is not the first chunk")
    if chunks[-1][0] != b"IEND":
        raise Bad("IEND is not the last chunk")
    w, h, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
    if width is not None and (w, h) != (width, height):
        raise Bad(f"{w}x{h} pixels, expected {width}x{height}")
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(color)
    if channels is None or depth != 8 or interlace != 0:
        raise Bad(f"unexpected format: colour type {color}, depth {depth}, interlace {interlace}")
    raw = zlib.decompress(b"".join(body for kind, body in chunks if kind == b"IDAT"))
    bpp, stride = channels, w * channels
    if len(raw) != h * (stride + 1):
        raise Bad(f"{len(raw)} bytes of image data, expected {h * (stride + 1)}")
    previous, first, varied = bytearray(stride), None, False
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = previous[x]
            c = previous[x - bpp] if x >= bpp else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + ((a + b) >> 1)) & 255
            elif kind == 4:
                line[x] = (line[x] + paeth(a, b, c)) & 255
            elif kind != 0:
                raise Bad(f"unknown filter {kind} in row {y}")
        if first is None:
            first = bytes(line[:bpp])
        if not varied and line != first * w:
            varied = True
        previous = line
    if not varied:
        raise Bad(f"every pixel is {first.hex()}: a blank picture")
    return f"PNG {w}x{h}"


def number(text):
    m = re.match(r"\s*([0-9.]+)", text or "")
    return float(m.group(1)) if m else None


def check_svg(data, width, height):
    try:
        root = ET.fromstring(data)
    except ET.ParseError as e:
        raise Bad(f"not well-formed XML: {e}")
    tag = lambda e: e.tag.rsplit("}", 1)[-1]
    if tag(root) != "svg":
        raise Bad(f"the root element is <{tag(root)}>, not <svg>")
    if width is not None:
        w, h = number(root.get("width")), number(root.get("height"))
        if (w, h) != (float(width), float(height)):
            raise Bad(f"width {root.get('width')!r}, height {root.get('height')!r}; expected {width}x{height}")
    drawn = [tag(e) for e in root.iter() if tag(e) not in ("svg", "rect", "g", "defs", "title", "desc")]
    if not drawn:
        raise Bad("it draws nothing but a background")
    return f"SVG <svg> with {len(drawn)} drawing elements ({', '.join(sorted(set(drawn)))})"


def check_pdf(data, width, height):
    if not data.startswith(b"%PDF-"):
        raise Bad("does not start with %PDF-")
    if not data.rstrip().endswith(b"%%EOF"):
        raise Bad("does not end with %%EOF")
    if width is not None:
        boxes = re.findall(rb"/MediaBox\s*\[\s*([-0-9. ]+)\]", data)
        sizes = {tuple(float(v) for v in box.split()) for box in boxes}
        if (0.0, 0.0, float(width), float(height)) not in sizes:
            raise Bad(f"no page of {width}x{height}: MediaBox {sorted(sizes)}")
    operators = 0
    for m in re.finditer(rb"stream\r?\n", data):
        end = data.find(b"endstream", m.end())
        try:
            content = zlib.decompress(data[m.end():end])
        except zlib.error:
            content = data[m.end():end]
        operators += len(re.findall(rb"(?<![A-Za-z])[mlc](?![A-Za-z])", content))
    if operators < 8:  # a background is one rectangle: re, or four l
        raise Bad(f"{operators} path operators: it draws nothing")
    return f"PDF with {operators} path operators"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--width", type=int)
    parser.add_argument("--height", type=int)
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    failed = False
    for name in args.files:
        try:
            with open(name, "rb") as f:
                data = f.read()
        except OSError as e:
            print(f"{name}: cannot read: {e}")
            failed = True
            continue
        check = {"png": check_png, "svg": check_svg, "pdf": check_pdf}.get(name.rsplit(".", 1)[-1].lower())
        try:
            if check is None:
                raise Bad("not a .png, .svg or .pdf name")
            print(f"{name}: {check(data, args.width, args.height)}")
        except Bad as e:
            print(f"{name}: {e}")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
