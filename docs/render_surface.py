#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Renders a face-coloured PLY from `texsyn --choosy-surface` to a PNG with POV-Ray 3.7.

usage: render_surface.py IN.ply OUT.png [--size 480x360] [--view X,Y,Z] [--up X,Y,Z]
                         [--fov DEG] [--keep-pov FILE.pov]

Python 3 standard library only; needs `povray` on PATH (Debian: apt-get install -y povray).
The PLY is binary little-endian: vertex x y z floats, face `list uchar int vertex_indices`,
then per-face properties. Face colours come from the float channels R G B (scene-linear, as
texsyn writes them; one float channel is shown as grey); without float channels the uchar
red green blue are decoded from sRGB. The scene uses assumed_gamma 1.0, so POV-Ray lights in
linear light and encodes the PNG as sRGB. Faces keep flat colours; the shading uses
area-weighted vertex normals. The camera looks along -VIEW (VIEW points from the object to
the camera, in the mesh's coordinates) and is placed so the projected vertices fill the
frame with a small margin.
"""
import argparse
import math
import os
import resource
import shutil
import struct
import subprocess
import sys
import tempfile
import time

PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def fail(message):
    sys.exit("render_surface.py: " + message)


def read_ply(path):
    """Returns (vertices [(x,y,z)], faces [(a,b,c)], colours [(r,g,b) linear])."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        fail(f"{path}: not a PLY file")
    body = end + len(b"end_header\n")
    elements = []  # [name, count, [(name, type or (count type, item type))]]
    for line in data[:end].decode("ascii").splitlines()[1:]:
        words = line.split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format":
            if words[1] != "binary_little_endian":
                fail(f"{path}: format {words[1]}, only binary_little_endian is read")
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property" and words[1] == "list":
            elements[-1][2].append((words[4], (PLY_TYPES[words[2]], PLY_TYPES[words[3]])))
        elif words[0] == "property":
            elements[-1][2].append((words[2], PLY_TYPES[words[1]]))
    vertices, faces, props = [], [], {}
    pos = body
    for name, count, properties in elements:
        lists = [p for p in properties if isinstance(p[1], tuple)]
        if not lists:
            record = struct.Struct("<" + "".join(t for _, t in properties))
            rows = list(record.iter_unpack(data[pos:pos + record.size * count]))
            pos += record.size * count
            if name == "vertex":
                names = [n for n, _ in properties]
                ix, iy, iz = names.index("x"), names.index("y"), names.index("z")
                vertices = [(r[ix], r[iy], r[iz]) for r in rows]
            continue
        if name != "face" or len(lists) != 1 or properties[0] is not lists[0]:
            fail(f"{path}: element {name}: only a leading vertex_indices list is read")
        count_type, item_type = properties[0][1]
        scalars = properties[1:]
        # texsyn writes triangles only: read fixed-size records, and check every count.
        record = struct.Struct("<" + count_type + item_type * 3 + "".join(t for _, t in scalars))
        rows = list(record.iter_unpack(data[pos:pos + record.size * count]))
        pos += record.size * count
        if len(rows) != count or any(r[0] != 3 for r in rows):
            fail(f"{path}: faces must all be triangles")
        faces = [r[1:4] for r in rows]
        for k, (pname, ptype) in enumerate(scalars):
            props[pname] = (ptype, [r[4 + k] for r in rows])
    if not vertices or not faces:
        fail(f"{path}: no vertices or no faces")
    floats = [n for n, (t, _) in props.items() if t in "fd"]
    if all(c in floats for c in "RGB"):
        colours = list(zip(props["R"][1], props["G"][1], props["B"][1]))
    elif len(floats) >= 3:
        colours = list(zip(*(props[n][1] for n in floats[:3])))
    elif len(floats) >= 1:
        colours = [(v, v, v) for v in props[floats[0]][1]]
    elif all(c in props for c in ("red", "green", "blue")):
        lut = [srgb_to_linear(i / 255.0) for i in range(256)]
        colours = [(lut[r], lut[g], lut[b])
                   for r, g, b in zip(props["red"][1], props["green"][1], props["blue"][1])]
    else:
        fail(f"{path}: no per-face colours (float channels or uchar red green blue)")
    return vertices, faces, colours


def srgb_to_linear(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def linear_to_srgb(v):
    v = min(max(v, 0.0), 1.0)
    return v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1.0 / 2.4) - 0.055


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(a):
    n = math.sqrt(dot(a, a))
    if n == 0.0:
        fail("zero-length --view or --up, or --view parallel to --up")
    return (a[0] / n, a[1] / n, a[2] / n)


def vertex_normals(vertices, faces):
    """Area-weighted vertex normals (the unnormalised face cross product weighs by area)."""
    acc = [[0.0, 0.0, 0.0] for _ in vertices]
    for a, b, c in faces:
        pa = vertices[a]
        n = cross(sub(vertices[b], pa), sub(vertices[c], pa))
        for i in (a, b, c):
            s = acc[i]
            s[0] += n[0]
            s[1] += n[1]
            s[2] += n[2]
    out = []
    for s in acc:
        length = math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) or 1.0
        out.append((s[0] / length, s[1] / length, s[2] / length))
    return out


def frame(vertices, view, up, fov_deg, aspect, margin=1.06):
    """Camera location and look_at so that every vertex is inside the picture."""
    back = unit(view)  # from the object towards the camera
    right = unit(cross(up, back))
    upv = cross(back, right)
    xs = [dot(v, right) for v in vertices]
    ys = [dot(v, upv) for v in vertices]
    zs = [dot(v, back) for v in vertices]
    cx, cy = 0.5 * (min(xs) + max(xs)), 0.5 * (min(ys) + max(ys))
    tan_h = math.tan(math.radians(fov_deg) / 2.0) / margin
    tan_v = tan_h / aspect
    # A point at (x, y, z) in the camera frame centred on (cx, cy) fits when the camera is at
    # least z + |x - cx| / tan_h (and the same with y, tan_v) away along `back`.
    d = max(z + max(abs(x - cx) / tan_h, abs(y - cy) / tan_v) for x, y, z in zip(xs, ys, zs))
    zc = 0.5 * (min(zs) + max(zs))
    centre = tuple(cx * right[i] + cy * upv[i] + zc * back[i] for i in range(3))
    location = tuple(cx * right[i] + cy * upv[i] + d * back[i] for i in range(3))
    return location, centre, right, upv, back


def pov_vec(v):
    # POV-Ray is left-handed (x right, y up, z into the screen); negating z keeps the mesh's
    # right-handed geometry unmirrored in the picture.
    return f"<{v[0]:.6g},{v[1]:.6g},{-v[2]:.6g}>"


def write_scene(path, vertices, faces, colours, args):
    width, height = args.size
    location, centre, right, upv, back = frame(vertices, args.view, args.up, args.fov,
                                               width / height)
    radius = max(math.sqrt(dot(sub(v, centre), sub(v, centre))) for v in vertices)

    def light(az, el, dist):
        # Directions in the camera frame: azimuth to the right of the view, elevation above.
        a, e = math.radians(az), math.radians(el)
        d = [math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a)]
        return tuple(centre[i] + dist * radius * (d[0] * right[i] + d[1] * upv[i] + d[2] * back[i])
                     for i in range(3))

    key, fill = light(-40.0, 45.0, 8.0), light(60.0, 10.0, 8.0)
    key_size = 1.5 * radius  # the area light's edge: soft shadow edges
    # Identical colours share one texture; 12 bits per channel in sRGB-encoded terms is finer
    # than the 8-bit PNG, so this changes no pixel but keeps POV-Ray's parse small.
    index, textures, face_texture = {}, [], []
    for c in colours:
        q = tuple(round(linear_to_srgb(v) * 4095.0) for v in c)
        t = index.get(q)
        if t is None:
            t = index[q] = len(textures)
            textures.append(tuple(srgb_to_linear(v / 4095.0) for v in q))
        face_texture.append(t)
    normals = vertex_normals(vertices, faces)
    with open(path, "w") as f:
        w = f.write
        w("#version 3.7;\n")
        w("global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light rgb 1 }\n")
        w("background { rgb %.4f }\n" % srgb_to_linear(0.93))
        w(f"camera {{ perspective location {pov_vec(location)} look_at {pov_vec(centre)}\n"
          f"  sky {pov_vec(upv)} right x*{width / height:.6f} angle {args.fov:.3f} }}\n")
        s = key_size
        ax = tuple(s * r for r in right)
        ay = tuple(s * u for u in upv)
        if args.unlit:
            w("#declare F = finish { ambient 1 diffuse 0 specular 0 }\n")
        else:
            # No jitter in the area light: the same scene renders to the same pixels.
            w(f"light_source {{ {pov_vec(key)} rgb 0.85\n"
              f"  area_light {pov_vec(ax)}, {pov_vec(ay)}, 4, 4 adaptive 1 circular orient }}\n")
            w(f"light_source {{ {pov_vec(fill)} rgb 0.30 shadowless }}\n")
            w("#declare F = finish { ambient 0.15 diffuse 1.0 specular 0 }\n")
        w(f"mesh2 {{\n vertex_vectors {{ {len(vertices)},\n")
        w(",\n".join(pov_vec(v) for v in vertices))
        w(f"\n }}\n normal_vectors {{ {len(normals)},\n")
        w(",\n".join(pov_vec(n) for n in normals))
        w(f"\n }}\n texture_list {{ {len(textures)},\n")
        w("\n".join(f"texture{{pigment{{rgb<{r:.5f},{g:.5f},{b:.5f}>}} finish{{F}}}}"
                    for r, g, b in textures))
        w(f"\n }}\n face_indices {{ {len(faces)},\n")
        w(",\n".join(f"<{a},{b},{c}>,{t}" for (a, b, c), t in zip(faces, face_texture)))
        w("\n }\n}\n")
    return len(textures)


def parse_vec(text):
    try:
        v = tuple(float(x) for x in text.split(","))
    except ValueError:
        v = ()
    if len(v) != 3:
        raise argparse.ArgumentTypeError(f"'{text}' is not X,Y,Z")
    return v


def parse_size(text):
    try:
        w, h = (int(x) for x in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not WxH")
    return w, h


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ply")
    p.add_argument("png")
    p.add_argument("--size", type=parse_size, default=(480, 360), help="WxH (480x360)")
    p.add_argument("--view", type=parse_vec, default=(1.0, 0.6, 1.6),
                   help="direction from the object to the camera (1,0.6,1.6)")
    p.add_argument("--up", type=parse_vec, default=(0.0, 1.0, 0.0), help="up (0,1,0)")
    p.add_argument("--fov", type=float, default=30.0, help="horizontal angle, degrees (30)")
    p.add_argument("--unlit", action="store_true",
                   help="no lights: every face shows exactly its colour (for flat meshes)")
    p.add_argument("--keep-pov", help="also keep the POV-Ray scene in this file")
    args = p.parse_args()
    if shutil.which("povray") is None:
        fail("povray not found (Debian: apt-get install -y povray)")
    t0 = time.time()
    vertices, faces, colours = read_ply(args.ply)
    tmp = tempfile.mkdtemp(prefix="render_surface_")
    try:
        pov = os.path.join(tmp, "scene.pov")
        ntex = write_scene(pov, vertices, faces, colours, args)
        t1 = time.time()
        w, h = args.size
        cmd = ["povray", "-D", "-V", "+WT2", f"+W{w}", f"+H{h}", "+A0.05", "+AM2", "+R3",
               "+FN8", f"+I{pov}", f"+O{os.path.abspath(args.png)}"]
        run = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True)
        if run.returncode != 0 or not os.path.exists(args.png):
            sys.stderr.write(run.stderr[-3000:])
            fail(f"povray failed (exit {run.returncode})")
        if args.keep_pov:
            shutil.copy(pov, args.keep_pov)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"{args.png}: {len(faces)} faces, {ntex} colours, scene {t1 - t0:.1f} s, "
          f"povray {time.time() - t1:.1f} s ({cpu.ru_utime + cpu.ru_stime:.1f} s CPU)")


if __name__ == "__main__":
    main()
