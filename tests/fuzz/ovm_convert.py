#!/usr/bin/python3
"""Rewrites an ASCII .ovm file (as `hbc generate` writes it) as .hedra or .HYBRID, so that the
hedra and HYBRID fuzzers get small seeds of every cell type; the project has no writer for those
formats and the only real .hedra files are larger than a seed should be.

usage: ovm_convert.py IN.ovm OUT.hedra|OUT.HYBRID
"""
import sys


def read_ovm(path):
    lines = [l.split('#')[0].strip() for l in open(path)]
    lines = [l for l in lines if l]
    pos = 1  # after the header

    def section():
        nonlocal pos
        toks = lines[pos].split()
        if len(toks) == 2:
            pos += 1
            return int(toks[1])
        n = int(lines[pos + 1])
        pos += 2
        return n

    def rows(n):
        nonlocal pos
        out = [lines[pos + i].split() for i in range(n)]
        pos += n
        return out

    verts = rows(section())
    edges = [(int(a), int(b)) for a, b in rows(section())]
    faces = []
    for r in rows(section()):
        loop = []
        for h in map(int, r[1:]):
            a, b = edges[h >> 1]
            loop.append(b if h & 1 else a)
        faces.append(loop)
    cells = [[int(x) for x in r[1:]] for r in rows(section())]
    return verts, faces, cells


def main():
    src, dst = sys.argv[1], sys.argv[2]
    verts, faces, cells = read_ovm(src)
    out = []
    if dst.lower().endswith('.hedra'):
        out.append(f"{len(verts)} {len(faces)} {len(cells)}")
        out += [" ".join(v) for v in verts]
        out += [f"{len(f)} " + " ".join(str(v + 1) for v in f) for f in faces]
        out += [f"{len(c)} " + " ".join(str(-(hf >> 1) - 1 if hf & 1 else (hf >> 1) + 1) for hf in c)
                for c in cells]
    elif dst.lower().endswith('.hybrid'):
        out.append(f"{len(verts)} {len(faces)} {3 * len(cells)}")
        out += [" ".join(v) for v in verts]
        out += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
        for c in cells:
            out.append(f"{len(c)} " + " ".join(str(hf >> 1) for hf in c))
            out.append(f"{len(c)} " + " ".join(str(hf & 1) for hf in c))
        out += ["0"] * len(cells)
    else:
        sys.exit("output must end in .hedra or .HYBRID")
    with open(dst, 'w') as f:
        f.write("\n".join(out) + "\n")


if __name__ == '__main__':
    main()
