#!/usr/bin/env python3
"""Where `grape render --view` puts a 3-D follower, against the projection worked out here.

    check_render3.py PNG VIEW W H BOX POINT

BOX is x0,y0,z0,x1,y1,z1 (the scene's 3-D content box), POINT the follower's x,y,z, VIEW the
--view given. The expected pixel follows the documented picture: the box grown on every side
by 7% of its diagonal (the follower axes' length), its 8 corners projected (oblique: x + r·cos a·y,
−(z + r·sin a·y); perspective: a camera orbiting the box's centre at radius / sin(fov/2), picture
lateral·focal/depth), fitted into the picture with a 30-unit margin (uniform scale, centred).
The follower is the centroid of the pixels of its colour, orange (0.95, 0.55, 0.1). Exit 0 when
it lies within 1 pixel: the dot is a disc of radius 5 drawn over everything else, whose centroid
on the pixel grid lies within about 0.3 px of its centre (the lattice points inside a radius-4.5
circle are symmetric to within a row); a wrong sign or axis moves it by tens of pixels.
"""
import math
import struct
import sys
import zlib


def pixels(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat = 8, b""
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    assert depth == 8 and ctype in (2, 6), f"unexpected PNG format {depth}/{ctype}"
    bpp = 4 if ctype == 6 else 3
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[at]
        line = bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, bpp, rows


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def unit(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def main():
    png, view, W, H = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    box = [float(v) for v in sys.argv[5].split(",")]
    point = [float(v) for v in sys.argv[6].split(",")]
    lo, hi = box[:3], box[3:]
    grow = 0.07 * math.sqrt(dot(sub(hi, lo), sub(hi, lo)))
    lo, hi = [v - grow for v in lo], [v + grow for v in hi]
    kind, _, numbers = view.partition(":")
    args = [float(v) for v in numbers.split(",")] if numbers else []
    if kind == "oblique":
        angle, recede = args if args else [40.0, 0.8]
        rx, ry = recede * math.cos(math.radians(angle)), recede * math.sin(math.radians(angle))
        project = lambda p: (p[0] + rx * p[1], -(p[2] + ry * p[1]))
    else:
        az, el, fov = (args + [-60.0, 30.0, 45.0][len(args):])
        centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
        radius = 0.5 * math.sqrt(dot(sub(hi, lo), sub(hi, lo)))
        distance = radius / math.sin(math.radians(fov) / 2)
        a, e = math.radians(az), math.radians(el)
        eye = [centre[0] + distance * math.cos(e) * math.cos(a), centre[1] + distance * math.cos(e) * math.sin(a),
               centre[2] + distance * math.sin(e)]
        forward = unit(sub(centre, eye))
        right = unit(cross(forward, [0, 0, 1]))
        up = cross(right, forward)
        focal = 1 / math.tan(math.radians(fov) / 2)
        def project(p):
            d = sub(p, eye)
            z = dot(d, forward)
            return (dot(d, right) * focal / z, -dot(d, up) * focal / z)
    corners = [project([(hi if k & 1 else lo)[0], (hi if k & 2 else lo)[1], (hi if k & 4 else lo)[2]]) for k in range(8)]
    xs, ys = [c[0] for c in corners], [c[1] for c in corners]
    scale = min((W - 60) / (max(xs) - min(xs)), (H - 60) / (max(ys) - min(ys)))
    q = project(point)
    expected = (W / 2 + scale * (q[0] - (max(xs) + min(xs)) / 2), H / 2 + scale * (q[1] - (max(ys) + min(ys)) / 2))
    w, h, bpp, rows = pixels(png)
    found = [(x + 0.5, y + 0.5) for y in range(h) for x in range(w)
             if abs(rows[y][x * bpp] - 242) <= 40 and abs(rows[y][x * bpp + 1] - 140) <= 40 and abs(rows[y][x * bpp + 2] - 26) <= 40]
    if len(found) < 20:
        print(f"FAIL: {len(found)} orange pixels, expected a dot of about 78")
        return 1
    cx, cy = sum(p[0] for p in found) / len(found), sum(p[1] for p in found) / len(found)
    off = math.hypot(cx - expected[0], cy - expected[1])
    print(f"{view}: follower at ({cx:.2f}, {cy:.2f}), expected ({expected[0]:.2f}, {expected[1]:.2f}), off by {off:.2f} px")
    return 0 if off <= 1.0 else 1


sys.exit(main())
