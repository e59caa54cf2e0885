#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus: small valid meshes in every format and variant the
readers know (fuzz/corpus/<format>/). Deterministic; rerun after changing it and commit the
result (scripts/fuzz copies the seeds into a working corpus in the build folder).

    python3 fuzz/make_corpus.py [OUT_DIR]     # default: fuzz/corpus next to this script
"""
import os
import shutil
import struct
import sys

TET_V = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
TET_F = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
CUBE_V = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_Q = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
COLORS = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (200, 200, 10)]
# A pentagon and a triangle: polygons of more than four corners.
PENT_V = [(0, 0, 0), (1, 0, 0), (1.3, 0.9, 0), (0.5, 1.5, 0), (-0.3, 0.9, 0), (0.5, 0.5, 1)]
PENT_F = [(0, 1, 2, 3, 4), (0, 1, 5)]
# Non-convex polygons (ear-clipped on reading): an L-shaped face starting at its reflex corner
# and a ten-pointed star, in a tilted plane.
L_V = [(1, 1, 0.5), (1, 3, 1.5), (0, 3, 1.5), (0, 0, 0), (2, 0, 0), (2, 1, 0.5)]
STAR_V = [(round((1.0 if k % 2 == 0 else 0.4) * c, 6), round((1.0 if k % 2 == 0 else 0.4) * s_, 6), 0.0)
          for k, (c, s_) in enumerate((__import__("math").cos(k * 3.141592653589793 / 5),
                                       __import__("math").sin(k * 3.141592653589793 / 5)) for k in range(10))]
BOM = "\ufeff"


def num(x):
    return repr(float(x)) if isinstance(x, float) else str(x)


def vline(v):
    return " ".join(num(c) for c in v)


# ---------------------------------------------------------------- OBJ
def obj_files():
    out = {}
    out["tet.obj"] = "".join(f"v {vline(v)}\n" for v in TET_V) + "".join(
        "f " + " ".join(str(i + 1) for i in f) + "\n" for f in TET_F)
    out["cube_quads_comments.obj"] = ("# cube\nmtllib cube.mtl\no cube\ng side\ns 1\nusemtl red\n" +
                                      "".join(f"v {vline(v)}\n" for v in CUBE_V) +
                                      "".join("f " + " ".join(str(i + 1) for i in q) + "  # quad\n" for q in CUBE_Q))
    uv = [(0, 0), (1, 0), (0, 1), (1, 1)]
    out["tet_vt_vn.obj"] = ("".join(f"v {vline(v)}\n" for v in TET_V) +
                            "".join(f"vt {u} {w}\n" for u, w in uv) +
                            "".join(f"vn {vline(v)}\n" for v in TET_V) +
                            "".join("f " + " ".join(f"{i + 1}/{i + 1}/{i + 1}" for i in f) + "\n" for f in TET_F))
    out["tet_v_vn.obj"] = ("".join(f"v {vline(v)}\n" for v in TET_V) +
                           "".join(f"vn {vline(v)}\n" for v in TET_V) +
                           "".join("f " + " ".join(f"{i + 1}//{i + 1}" for i in f) + "\n" for f in TET_F))
    out["tet_colors.obj"] = "".join(f"v {vline(v)} {c[0] / 255} {c[1] / 255} {c[2] / 255}\n"
                                    for v, c in zip(TET_V, COLORS)) + "".join(
        "f " + " ".join(str(i + 1) for i in f) + "\n" for f in TET_F)
    out["tet_negative_indices.obj"] = "".join(f"v {vline(v)}\n" for v in TET_V) + "".join(
        "f " + " ".join(str(i - 4) for i in f) + "\n" for f in TET_F)
    out["pentagon_polyline.obj"] = ("".join(f"v {vline(v)}\n" for v in PENT_V) +
                                    "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in PENT_F) +
                                    "l 1 2 3\n")
    out["tet_crlf_exponents.obj"] = "".join(f"v {v[0]}e0 {v[1]}.0E+00 {v[2] * 0.5:.3e}\r\n" for v in TET_V) + "".join(
        "f " + " ".join(str(i + 1) for i in f) + "\r\n" for f in TET_F)
    # Tabs and other whitespace between every word, after a UTF-8 byte-order mark.
    out["tet_tabs_bom.obj"] = BOM + "".join(f"v\t{v[0]}\t {v[1]}\v{v[2]}\n" for v in TET_V) + "".join(
        "f\t" + "\t".join(str(i + 1) for i in f) + " \f\n" for f in TET_F)
    out["l_shape_star.obj"] = ("".join(f"v {vline(v)}\n" for v in L_V + STAR_V) + "f 1 2 3 4 5 6\n" +
                               "f " + " ".join(str(-10 + k) for k in range(10)) + "\n")
    return out


# ---------------------------------------------------------------- OFF
def off_files():
    out = {}
    body_f = "".join(f"3 {a} {b} {c}\n" for a, b, c in TET_F)
    out["tet.off"] = "OFF\n4 4 6\n" + "".join(vline(v) + "\n" for v in TET_V) + body_f
    out["tet_comments.off"] = ("# a comment\nOFF\n# counts\n4 4 0\n" + "".join(vline(v) + "  # vertex\n" for v in TET_V) +
                               "\n" + body_f)
    out["tet_one_line_header.off"] = "OFF 4 4 6\n" + "".join(vline(v) + "\n" for v in TET_V) + body_f
    out["tet_vertex_colors.off"] = "COFF\n4 4 6\n" + "".join(
        f"{vline(v)} {c[0]} {c[1]} {c[2]} 255\n" for v, c in zip(TET_V, COLORS)) + body_f
    out["tet_face_colors.off"] = "OFF\n4 4 6\n" + "".join(vline(v) + "\n" for v in TET_V) + "".join(
        f"3 {a} {b} {c} 0.5 0.25 1.0\n" for a, b, c in TET_F)
    out["tet_normals.off"] = "NOFF\n4 4 6\n" + "".join(f"{vline(v)} {vline(v)}\n" for v in TET_V) + body_f
    out["tet_colors_normals.off"] = "CNOFF\n4 4 6\n" + "".join(
        f"{vline(v)} {vline(v)} {c[0]} {c[1]} {c[2]}\n" for v, c in zip(TET_V, COLORS)) + body_f
    out["tet_homogeneous.off"] = "4OFF\n4 4 6\n" + "".join(f"{vline(v)} 1\n" for v in TET_V) + body_f
    out["cube_quads.off"] = "OFF\n8 6 12\n" + "".join(vline(v) + "\n" for v in CUBE_V) + "".join(
        "4 " + " ".join(map(str, q)) + "\n" for q in CUBE_Q)
    out["pentagon.off"] = "OFF\n6 2 0\n" + "".join(vline(v) + "\n" for v in PENT_V) + "".join(
        f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in PENT_F)
    out["tet_bom.off"] = BOM + out["tet.off"]
    out["l_shape_star.off"] = (f"OFF\n{len(L_V) + len(STAR_V)} 2 0\n" + "".join(vline(v) + "\n" for v in L_V + STAR_V) +
                               "6 0 1 2 3 4 5\n10 " + " ".join(str(6 + k) for k in range(10)) + "\n")
    b = b"OFF BINARY\n" + struct.pack(">iii", 4, 4, 6)
    for v in TET_V:
        b += struct.pack(">fff", *v)
    for f in TET_F:
        b += struct.pack(">iiiii", 3, *f, 0)  # count, indices, no colour components
    out["tet_binary.off"] = b
    return out


# ---------------------------------------------------------------- PLY
PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I", "float": "f",
             "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I",
             "float32": "f", "float64": "d"}


def ply(fmt, vprops, vrows, fprops, frows, extra_header="", extra_elements=()):
    """vprops: [(type, name)]; fprops: [("list", count_type, item_type, name) | (type, name)]."""
    h = f"ply\nformat {fmt} 1.0\n{extra_header}"
    h += f"element vertex {len(vrows)}\n" + "".join(f"property {t} {n}\n" for t, n in vprops)
    h += f"element face {len(frows)}\n"
    for p in fprops:
        h += (f"property list {p[1]} {p[2]} {p[3]}\n" if p[0] == "list" else f"property {p[0]} {p[1]}\n")
    for name, props, rows in extra_elements:
        h += f"element {name} {len(rows)}\n" + "".join(f"property {t} {n}\n" for t, n in props)
    h += "end_header\n"
    if fmt == "ascii":
        body = "".join(" ".join(num(x) for x in r) + "\n" for r in vrows)
        for r in frows:
            parts = []
            for p, x in zip(fprops, r):
                parts += [str(len(x))] + [str(i) for i in x] if p[0] == "list" else [num(x)]
            body += " ".join(parts) + "\n"
        for _, props, rows in extra_elements:
            body += "".join(" ".join(num(x) for x in r) + "\n" for r in rows)
        return (h + body).encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b""
    for r in vrows:
        body += b"".join(struct.pack(e + PLY_TYPES[t], x) for (t, _), x in zip(vprops, r))
    for r in frows:
        for p, x in zip(fprops, r):
            if p[0] == "list":
                body += struct.pack(e + PLY_TYPES[p[1]], len(x)) + b"".join(struct.pack(e + PLY_TYPES[p[2]], i) for i in x)
            else:
                body += struct.pack(e + PLY_TYPES[p[0]], x)
    for _, props, rows in extra_elements:
        for r in rows:
            body += b"".join(struct.pack(e + PLY_TYPES[t], x) for (t, _), x in zip(props, r))
    return h.encode() + body


def ply_files():
    out = {}
    xyz_f = [("float", "x"), ("float", "y"), ("float", "z")]
    xyz_d = [("double", "x"), ("double", "y"), ("double", "z")]
    idx = [("list", "uchar", "int", "vertex_indices")]
    tv = [tuple(float(c) for c in v) for v in TET_V]
    tf = [(f,) for f in TET_F]
    for fmt, tag in (("ascii", "ascii"), ("binary_little_endian", "le"), ("binary_big_endian", "be")):
        out[f"tet_{tag}.ply"] = ply(fmt, xyz_f, tv, idx, tf)
    out["tet_le_double_uint_counts.ply"] = ply("binary_little_endian", xyz_d, tv,
                                               [("list", "uint", "uint", "vertex_indices")], tf)
    out["tet_be_double_int_counts.ply"] = ply("binary_big_endian", xyz_d, tv,
                                              [("list", "int", "int", "vertex_indices")], tf)
    rgb = xyz_f + [("uchar", "red"), ("uchar", "green"), ("uchar", "blue")]
    crow = [v + c for v, c in zip(tv, COLORS)]
    out["tet_colors_ascii.ply"] = ply("ascii", rgb, crow, idx, tf, "comment vertex colours\nobj_info made by make_corpus\n")
    out["tet_colors_le.ply"] = ply("binary_little_endian", rgb + [("uchar", "alpha")], [r + (255,) for r in crow], idx, tf)
    nuv = xyz_f + [("float", "nx"), ("float", "ny"), ("float", "nz"), ("float", "texture_u"), ("float", "texture_v")]
    urow = [v + v + (0.25 * i, 0.5) for i, v in enumerate(tv)]
    out["tet_normals_uv_ascii.ply"] = ply("ascii", nuv, urow, idx, tf)
    out["tet_normals_uv_be.ply"] = ply("binary_big_endian", nuv, urow, idx, tf)
    st = xyz_f + [("float", "s"), ("float", "t")]
    out["tet_st_ascii.ply"] = ply("ascii", st, [v + (0.1, 0.2) for v in tv], [("list", "uchar", "uint", "vertex_index")], tf)
    fcol = idx + [("uchar", "red"), ("uchar", "green"), ("uchar", "blue")]
    out["tet_face_colors_le.ply"] = ply("binary_little_endian", xyz_f, tv, fcol, [(f,) + c for f, c in zip(TET_F, COLORS)])
    cv = [tuple(float(c) for c in v) for v in CUBE_V]
    out["cube_quads_ascii.ply"] = ply("ascii", xyz_f, cv, idx, [(q,) for q in CUBE_Q])
    out["cube_quads_edges_le.ply"] = ply("binary_little_endian", xyz_f, cv, idx, [(q,) for q in CUBE_Q],
                                         extra_elements=[("edge", [("int", "vertex1"), ("int", "vertex2")],
                                                          [(0, 1), (1, 3), (3, 2)])])
    pv = [tuple(float(c) for c in v) for v in PENT_V]
    out["pentagon_ascii.ply"] = ply("ascii", xyz_f, pv, idx, [(f,) for f in PENT_F])
    out["tet_other_props_le.ply"] = ply("binary_little_endian",
                                        [("short", "flags")] + xyz_f + [("ushort", "quality"), ("char", "tag")],
                                        [(7,) + v + (3, -1) for v in tv],
                                        [("int", "id")] + idx + [("list", "uchar", "float", "texcoord")],
                                        [(i, f, (0.0, 0.5, 1.0, 0.5, 0.0, 1.0)) for i, f in enumerate(TET_F)])
    # Face lists of every integer type; a BOM before "ply"; non-convex polygons.
    for fmt, tag in (("ascii", "ascii"), ("binary_little_endian", "le"), ("binary_big_endian", "be")):
        for count, item in (("uchar", "uchar"), ("ushort", "ushort"), ("char", "short")):
            out[f"tet_{tag}_{count}_{item}_indices.ply"] = ply(fmt, xyz_f, tv, [("list", count, item, "vertex_indices")], tf)
    out["tet_bom_ascii.ply"] = BOM.encode() + out["tet_ascii.ply"]
    lv = [tuple(float(c) for c in v) for v in L_V + STAR_V]
    out["l_shape_star_le.ply"] = ply("binary_little_endian", xyz_d, lv, idx, [(tuple(range(6)),), (tuple(range(6, 16)),)])
    return out


# ---------------------------------------------------------------- STL
def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def stl_ascii(V, F, name="tet", nl="\n"):
    s = f"solid {name}{nl}"
    for f in F:
        tri = [V[i] for i in f]
        s += f"  facet normal {vline(normal(*tri))}{nl}    outer loop{nl}"
        s += "".join(f"      vertex {vline(p)}{nl}" for p in tri)
        s += f"    endloop{nl}  endfacet{nl}"
    return s + f"endsolid {name}{nl}"


def stl_binary(V, F, header=b"binary STL from make_corpus", attr=0):
    b = header.ljust(80, b" ")[:80] + struct.pack("<I", len(F))
    for f in F:
        tri = [V[i] for i in f]
        b += struct.pack("<3f", *normal(*tri)) + b"".join(struct.pack("<3f", *p) for p in tri) + struct.pack("<H", attr)
    return b


def stl_files():
    cube_t = [t for q in CUBE_Q for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return {
        "tet_ascii.stl": stl_ascii(TET_V, TET_F),
        "tet_ascii_crlf_noname.stl": stl_ascii(TET_V, TET_F, name="", nl="\r\n"),
        "tet_ascii_bom.stl": BOM + stl_ascii(TET_V, TET_F),
        "cube_ascii_floats.stl": stl_ascii([tuple(0.5 * c + 0.125 for c in v) for v in CUBE_V], cube_t, "cube"),
        "tet_binary.stl": stl_binary(TET_V, TET_F),
        "tet_binary_solid_header.stl": stl_binary(TET_V, TET_F, header=b"solid tet (binary, exported by a tool)"),
        "cube_binary_attributes.stl": stl_binary(CUBE_V, cube_t, attr=0x7C1F),
    }


def gltf_parts(vertices, faces, uv=None, colors=None):
    """The JSON document (without buffer uri) and the binary buffer of a glTF mesh."""
    import json
    bin_ = b"".join(struct.pack("<3f", *v) for v in vertices)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(bin_)}]
    acc = [{"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3",
            "min": [min(v[i] for v in vertices) for i in range(3)],
            "max": [max(v[i] for v in vertices) for i in range(3)]}]
    attributes = {"POSITION": 0}
    for name, rows, kind, fmt in (("TEXCOORD_0", uv, "VEC2", "<2f"), ("COLOR_0", colors, "VEC4", "<4B")):
        if rows:
            data = b"".join(struct.pack(fmt, *r) for r in rows)
            views.append({"buffer": 0, "byteOffset": len(bin_), "byteLength": len(data)})
            bin_ += data
            acc.append({"bufferView": len(views) - 1, "componentType": 5126 if fmt == "<2f" else 5121,
                        "count": len(rows), "type": kind, "normalized": fmt != "<2f"})
            attributes[name] = len(acc) - 1
    idx = b"".join(struct.pack("<3H", *f) for f in faces)
    views.append({"buffer": 0, "byteOffset": len(bin_), "byteLength": len(idx)})
    bin_ += idx
    acc.append({"bufferView": len(views) - 1, "componentType": 5123, "count": 3 * len(faces), "type": "SCALAR"})
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": attributes, "indices": len(acc) - 1, "material": 0}]}],
           "materials": [{"name": "m"}], "buffers": [{"byteLength": len(bin_)}], "bufferViews": views,
           "accessors": acc}
    return doc, bin_


def gltf_files():
    import base64
    import json
    out = {}
    uv = [(0, 0), (1, 0), (0, 1), (1, 1)]
    for name, kw in (("tet.gltf", {}), ("tet_uv_colors.gltf", {"uv": uv, "colors": [c + (255,) for c in COLORS]})):
        doc, bin_ = gltf_parts(TET_V, TET_F, **kw)
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bin_).decode()
        out[name] = json.dumps(doc)
    return out


def glb_files():
    import json
    doc, bin_ = gltf_parts(TET_V, TET_F, uv=[(0, 0), (1, 0), (0, 1), (1, 1)])
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    bin_ += b"\0" * (-len(bin_) % 4)
    body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bin_), b"BIN\0") + bin_
    return {"tet.glb": struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body}


def gz_files():
    import gzip
    # mtime 0: deterministic bytes.
    return {name + ".gz": gzip.compress(data.encode(), mtime=0) for name, data in obj_files().items() if "tet" in name}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    for fmt, files in (("obj", obj_files()), ("off", off_files()), ("ply", ply_files()), ("stl", stl_files()),
                       ("gltf", gltf_files()), ("glb", glb_files()), ("obj.gz", gz_files())):
        d = os.path.join(out, fmt)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        for name, data in files.items():
            with open(os.path.join(d, name), "wb") as fh:
                fh.write(data.encode() if isinstance(data, str) else data)


if __name__ == "__main__":
    main()
