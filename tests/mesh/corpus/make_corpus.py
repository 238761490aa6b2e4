#!/usr/bin/env python3
"""Writes the malformed-mesh corpus used by tests/mesh/mesh_check_corpus_test.cc.

Each file is small and deterministic; EXPECTED.tsv (kept by hand next to this script) lists
the exit code `ergo_mesh check` must give for each and a piece of the message it must print.
Run from this folder: python3 make_corpus.py
"""
import random
import struct

# A positively oriented tetrahedron 0.1 m across, with outward faces (0-based).
TET_POINTS = [(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1)]
TET_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]

# A cube 0.1 m wide, 12 outward triangles.
CUBE_POINTS = [(x, y, z) for x in (0, 0.1) for y in (0, 0.1) for z in (0, 0.1)]
CUBE_FACES = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
              (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]


def write(name, text):
    with open(name, "w", newline="") as f:
        f.write(text)


def write_bytes(name, data):
    with open(name, "wb") as f:
        f.write(data)


def off(points, faces, header=None):
    lines = [header or "OFF", f"{len(points)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in p) for p in points]
    lines += ["3 " + " ".join(str(i) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def obj(points, faces):
    lines = ["v " + " ".join(repr(float(c)) for c in p) for p in points]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def binary_stl(points, faces, header=b"ergo corpus"):
    data = header.ljust(80, b" ")[:80] + struct.pack("<I", len(faces))
    for f in faces:
        data += struct.pack("<3f", 0, 0, 0)
        for i in f:
            data += struct.pack("<3f", *points[i])
        data += b"\0\0"
    return data


def ascii_stl(points, faces, scale=1.0):
    out = ["solid corpus"]
    for f in faces:
        out += ["facet normal 0 0 0", " outer loop"]
        out += ["  vertex " + " ".join(repr(c * scale) for c in points[i]) for i in f]
        out += [" endloop", "endfacet"]
    return "\n".join(out) + "\nendsolid corpus\n"


def main():
    rng = random.Random(20240611)

    # --- Unusable: the file cannot be read. ---
    write("truncated_vertices.off", off(CUBE_POINTS, CUBE_FACES).split("0.1 0.0 0.0")[0])
    text = off(CUBE_POINTS, CUBE_FACES).replace("8 12 0", "8 20 0")
    write("wrong_face_count.off", text)
    write("huge_counts.off", "OFF\n353535235358 6 0\n-0.5 -0.5 0.5\n0.5 -0.5 0.5\n")
    write("nan_vertex.obj", obj(TET_POINTS, TET_FACES).replace("v 0.0 0.0 0.1", "v 0.0 nan 0.1"))
    write("inf_vertex.off", off(TET_POINTS, TET_FACES).replace("0.1 0.0 0.0", "inf 0.0 0.0"))
    write("index_out_of_range.obj", obj(TET_POINTS, TET_FACES) + "f 1 2 9\n")
    write("index_zero.obj", obj(TET_POINTS, TET_FACES) + "f 0 1 2\n")
    write("negative_index.off", off(TET_POINTS, TET_FACES).replace("3 1 2 3", "3 1 -2 3"))
    write("bad_number.obj", "v 0 0 0\nv 1 0 0\nv 0 1 3.1+e2\nf 1 2 3\n")
    write("empty_face.obj", obj(TET_POINTS, TET_FACES) + "f\n")
    write("empty.obj", "")
    write("points_only.obj", "# a point cloud\nv 0 0 0\nv 0.1 0 0\nv 0 0.1 0\np 1 2 3\n")
    write("not_a_mesh.off", "hello world\nthis is not a mesh\n")
    write("no_counts.off", "OFF\n# only a comment\n")
    write("wrong_extension.xyz", obj(TET_POINTS, TET_FACES))
    write_bytes("binary_in_text.obj", b"v 0 0 0\nv 1 0 0\nv 0 1\x00\x07 0\nf 1 2 3\n")
    write_bytes("binary_garbage.stl", bytes(rng.randrange(256) for _ in range(1000)))
    huge = bytearray(binary_stl(TET_POINTS, TET_FACES))
    huge[80:84] = struct.pack("<I", 10**9)
    write_bytes("huge_count.stl", bytes(huge) + bytes(800))
    write_bytes("truncated_binary.stl",
                binary_stl(CUBE_POINTS, CUBE_FACES, b"binary, cut short")[:84 + 50 * 5 + 17])
    write("truncated_ascii.stl", ascii_stl(TET_POINTS, TET_FACES).split("endloop")[0][:-20])
    write_bytes("garbage_header.ply",
                b"ply\nformat binary_little_endian 1.0\nelement vertex 4\n" +
                bytes(rng.choice([b for b in range(1, 256) if b not in (10, 13)])
                      for _ in range(300)) + b"\x00\x01")
    write("no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")
    write_bytes("huge_count.ply",
                b"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
                b"property float x\nproperty float y\nproperty float z\nelement face 1\n"
                b"property list uchar int vertex_indices\nend_header\n" + bytes(64))
    body = b"".join(struct.pack("<3f", *p) for p in TET_POINTS)
    write_bytes("truncated_binary.ply",
                b"ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                b"property float x\nproperty float y\nproperty float z\nelement face 4\n"
                b"property list uchar int vertex_indices\nend_header\n" + body +
                b"\x03" + struct.pack("<3i", 0, 2, 1) + b"\x03" + struct.pack("<i", 0))
    write("missing_indices.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int corners\nend_header\n"
          "0 0 0\n0.1 0 0\n0 0.1 0\n3 0 1 2\n")
    write("short_record.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nproperty float nx\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n"
          "0 0 0 1\n0.1 0 0\n0 0.1 0 1\n3 0 1 2\n")
    write("v1.msh", "$NOD\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$ENDNOD\n$ELM\n1\n1 2 0 1 3 1 2 3\n"
          "$ENDELM\n")
    write("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n")
    write("binary_v4.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n")
    write("bad_tag_count.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n"
          "4 0 0 0.1\n$EndNodes\n$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 2 2 0 1 1 2 3 4\n"
          "$EndElements\n")
    write("missing_node.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n"
          "4 0 0 0.1\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 7\n$EndElements\n")
    write("truncated.msh",
          "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n"
          "0 0 0\n0.1 0 0\n")
    write("block_count_lie.msh",
          "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n"
          "0 0 0\n0.1 0 0\n0 0.1 0\n0 0 0.1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 50\n"
          "1 1 2 3 4\n$EndElements\n")
    write("triangle_2d.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n")
    write("triangle_2d.ele", "2 3 0\n1 1 2 3\n2 2 4 3\n")
    write("ele_out_of_range.node", "4 3 0 0\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n4 0 0 0.1\n")
    write("ele_out_of_range.ele", "1 4 0\n1 1 2 3 5\n")

    # --- Problems: readable, but wrong for ergo. ---
    write("open_box.obj", obj(CUBE_POINTS, CUBE_FACES[:-2]))
    flipped = list(TET_FACES)
    flipped[3] = (1, 3, 2)
    write("flipped_face.off", off(TET_POINTS, flipped))
    write("inward_cube.off", off(CUBE_POINTS, [(a, c, b) for a, b, c in CUBE_FACES]))
    write("non_manifold_edge.obj", obj(TET_POINTS + [(0.05, 0.05, -0.1)],
                                       TET_FACES + [(0, 1, 4)]))
    write("degenerate.obj", obj(TET_POINTS + [(0.05, 0, 0)], TET_FACES + [(0, 4, 1)]))
    write("duplicate_vertices.obj", obj(TET_POINTS + [(0.1, 0, 0)],
                                        [(0, 2, 4), (0, 1, 3), (0, 3, 2), (1, 2, 3)]))
    write("millimetres.stl", ascii_stl(CUBE_POINTS, CUBE_FACES, scale=10000.0))
    write("tiny.obj", obj([(x * 0.01, y * 0.01, z * 0.01) for x, y, z in TET_POINTS], TET_FACES))
    shifted = [(x + 0.03, y + 0.03, z + 0.03) for x, y, z in TET_POINTS]
    write("self_intersecting.off",
          off(TET_POINTS + shifted, TET_FACES + [(a + 4, b + 4, c + 4) for a, b, c in TET_FACES]))
    write("inverted_tets.node", "5 3 0 0\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n4 0 0 0.1\n"
          "5 0.1 0.1 0.1\n")
    write("inverted_tets.ele", "2 4 0\n1 1 2 3 4\n2 2 4 3 5\n")
    write("zero_volume.msh",
          "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 5 1 5\n3 1 0 5\n1\n2\n3\n4\n5\n"
          "0 0 0\n0.1 0 0\n0 0.1 0\n0 0 0.1\n0.05 0.05 0\n$EndNodes\n$Elements\n1 2 1 2\n"
          "3 1 4 2\n1 1 2 3 4\n2 1 2 3 5\n$EndElements\n")
    write("short_face.obj", obj(TET_POINTS, TET_FACES) + "f 1 2\n")

    # --- Readable and clean, with format features readers must handle. ---
    write_bytes("crlf_bom_comments.obj",
                b"\xef\xbb\xbf# tetrahedron\r\n" +
                obj(TET_POINTS, TET_FACES).replace("\n", "  # c\r\n").encode())
    write_bytes("utf16.obj", b"\xff\xfe" + obj(TET_POINTS, TET_FACES).encode("utf-16-le"))
    write_bytes("solid_header_binary.stl",
                binary_stl(TET_POINTS, TET_FACES, b"solid but actually binary"))
    write("quads_wrapped.off",
          "COFF\n# cube as quads, a face record wrapped over two lines\n8 6 0\n" +
          "\n".join(" ".join(repr(float(c)) for c in p) + " 255 0 0" for p in CUBE_POINTS) +
          "\n4 0 1 3\n 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n")


if __name__ == "__main__":
    main()
