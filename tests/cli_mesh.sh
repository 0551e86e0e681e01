#!/usr/bin/env bash
# The mesh method and `fluidsurf mesh` from the CLI (a build with OpenVDB): the
# bundled dam break against the reference through compare and diff at 128x128;
# `fluidsurf mesh` to .ply, .obj, .vtk and .vtp, each read back by VTK's own
# readers (python3-vtk9) with the vertex and triangle counts --timings printed;
# a {} sequence in and out; smooth=weighted; attributes in the PLY and VTP; render --export; refused parameters, formats and
# paths (exit 2, one line, nothing left behind).
# usage: tests/cli_mesh.sh BIN SRC OUT
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
scene=$SRC/experiments/scenes/dam_break.json
dam=$SRC/experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply
"$BIN" methods | grep -q '^mesh' ; check '[ $? -eq 0 ]' "mesh is registered"
"$BIN" compare "$scene" --methods mesh -W 128 -H 128 --repeat 1 -q --no-cache -o "$T/cmp" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/cmp/mesh.exr" ]' "compare mesh at 128x128 ($(head -c 200 "$T/err"))"
"$BIN" diff "$T/cmp/mesh.exr" "$T/cmp/reference.exr" --fail-iou 0.97 --fail-depth-r 1 --fail-normal-deg 5 > "$T/diff.txt" 2>&1; rc=$?
cat "$T/diff.txt"
check '[ $rc -eq 0 ]' "mesh vs reference: IoU >= 0.97, depth within 1 r, normal mean <= 5 deg"
# every export, read back through VTK
for ext in ply obj vtk vtp; do
  "$BIN" mesh "$dam" --radius 0.025 -o "$T/dam.$ext" --timings -q > "$T/t_$ext.csv" 2> "$T/err"; rc=$?
  check '[ $rc -eq 0 ] && [ -s "$T/dam.$ext" ]' "fluidsurf mesh -o dam.$ext ($(head -c 200 "$T/err"))"
  counts=$(awk -F, '$2 == "total" {print $4, $5}' "$T/t_$ext.csv")
  read -r nv nt <<< "$counts"
  got=$(/usr/bin/python3 - "$T/dam.$ext" <<'PY' 2>&1
import sys, vtk
p = sys.argv[1]
r = {"ply": vtk.vtkPLYReader, "obj": vtk.vtkOBJReader, "vtk": vtk.vtkPolyDataReader, "vtp": vtk.vtkXMLPolyDataReader}[p.rsplit(".", 1)[1]]()
r.SetFileName(p)
r.Update()
d = r.GetOutput()
n = d.GetPointData().GetNormals()
tri = all(d.GetCell(i).GetNumberOfPoints() == 3 for i in range(0, d.GetNumberOfCells(), 997))
print(d.GetNumberOfPoints(), d.GetNumberOfPolys(), n.GetNumberOfTuples() if n else 0, int(tri))
PY
)
  # OBJ's reader duplicates a vertex per distinct position/normal pair: it may hold more points, never fewer
  check '[ -n "$nv" ] && awk -v g="$got" -v nv="$nv" -v nt="$nt" -v e="$ext" "BEGIN { split(g, a, \" \"); exit !((a[1] == nv || (e == \"obj\" && a[1] >= nv)) && a[2] == nt && a[3] == a[1] && a[4] == 1) }"' \
    "VTK reads dam.$ext: points, triangles, normals '$got' against $nv vertices, $nt triangles"
done
check '[ "$(cut -d, -f4,5 "$T/t_ply.csv" | sort -u)" = "$(cut -d, -f4,5 "$T/t_vtp.csv" | sort -u)" ]' "the same mesh for every format"
# a {} sequence: two frames in, two files out
cp "$dam" "$T/f_3.ply"
"$BIN" convert "$SRC/experiments/data/splashsurf/cube_2366_particles.vtk" -o "$T/f_4.ply" 2> "$T/err"
"$BIN" mesh "$T/f_{}.ply" --frames 3:4 --radius 0.025 -o "$T/seq_{}.obj" 2> "$T/progress"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/seq_3.obj" ] && [ -s "$T/seq_4.obj" ] && grep -q "2/2 frames" "$T/progress"' "a {} sequence: seq_3.obj, seq_4.obj and a progress bar ($(tail -c 200 "$T/progress"))"
# splashsurf's recipe: weighted smoothing (25 steps as its README) writes a mesh of about the same size (the
# faces it leaves degenerate collapsed: under 0.1% fewer)
"$BIN" mesh "$dam" --radius 0.025 --set mesh.smooth=weighted --set mesh.smooth_iters=25 -o "$T/w.ply" --timings -q > "$T/t_w.csv" 2> "$T/err"; rc=$?
read -r wv wt <<< "$(awk -F, '$2 == "total" {print $4, $5}' "$T/t_w.csv")"
check '[ $rc -eq 0 ] && [ -s "$T/w.ply" ] && [ -n "$wt" ] && [ "$wt" -le "$nt" ] && [ $((wt * 1000)) -ge $((nt * 999)) ] && grep -q ",smooth," "$T/t_w.csv"' "fluidsurf mesh --set mesh.smooth=weighted: $wv vertices, $wt triangles (unsmoothed $nt), a smooth stage ($(head -c 200 "$T/err"))"
# every mesh file carries the provenance an EXR carries: PLY and OBJ comments, VTK field data
for f in w.ply dam.obj dam.vtk dam.vtp; do
  got=$(/usr/bin/python3 - "$T/$f" <<'PY' 2>&1
import sys, vtk
p = sys.argv[1]
if p.endswith((".ply", ".obj")):
    text = open(p, "rb").read(4000).decode("latin-1")
    pre = "comment " if p.endswith(".ply") else "# "
    prov = dict(l[len(pre) + 10:].split("=", 1) for l in text.splitlines() if l.startswith(pre + "fluidsurf:"))
else:
    r = vtk.vtkPolyDataReader() if p.endswith(".vtk") else vtk.vtkXMLPolyDataReader()
    r.SetFileName(p)
    r.Update()
    fd = r.GetOutput().GetFieldData()
    prov = {fd.GetAbstractArray(i).GetName()[10:]: fd.GetAbstractArray(i).GetValue(0) for i in range(fd.GetNumberOfArrays())}
need = ["commit", "dirty", "source", "r", "r_source", "field", "method", "params", "frame"]
print(" ".join(k for k in need if k not in prov) or "all", prov.get("r"), prov.get("params", "")[:40])
PY
)
  check '[[ "$got" == "all 0.025"* ]] && { [ "$f" != w.ply ] || [[ "$got" == *smooth=weighted\;smooth_iters=25* ]]; }' "$f carries the provenance (missing: $got)"
done
check '! cmp -s "$T/w.ply" "$T/dam.ply"' "weighted smoothing moves the vertices"
# mesh.attributes=on: the particles' velocity and colour at the vertices, in the PLY and the VTP
/usr/bin/python3 - "$T/attr_in.ply" <<'PY'
import struct, sys
pts = [(0.05 * i, 0.05 * j, 0.05 * k) for i in range(8) for j in range(8) for k in range(3)]
with open(sys.argv[1], "wb") as f:
    f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % len(pts)).encode())
    for n in ("x", "y", "z", "vx", "vy", "vz", "red", "green", "blue"):
        f.write(("property float %s\n" % n).encode())
    f.write(b"end_header\n")
    for p in pts:
        f.write(struct.pack("<9f", *p, 1.0, -2.0, 0.5, 0.2, 0.4, 0.6))
PY
for ext in ply vtp; do
  "$BIN" mesh "$T/attr_in.ply" --radius 0.025 --set mesh.attributes=on -o "$T/attr.$ext" -q 2> "$T/err"; rc=$?
  got=$(/usr/bin/python3 - "$T/attr.$ext" <<'PY' 2>&1
import sys, vtk
p = sys.argv[1]
r = vtk.vtkPLYReader() if p.endswith(".ply") else vtk.vtkXMLPolyDataReader()
r.SetFileName(p)
r.Update()
d = r.GetOutput()
pd = d.GetPointData()
if p.endswith(".ply"):  # VTK's PLY reader keeps no vx or float colours: read the header
    head = open(p, "rb").read(6000).split(b"end_header")[0].decode("latin-1")
    print(d.GetNumberOfPoints() > 0, "property float vx" in head, "property float red" in head)
else:
    v, c = pd.GetArray("velocity"), pd.GetArray("color")
    ok = v is not None and c is not None and v.GetNumberOfTuples() == d.GetNumberOfPoints() > 0
    ok = ok and all(abs(v.GetComponent(i, 1) + 2) < 1e-5 and abs(c.GetComponent(i, 2) - 0.6) < 1e-5 for i in range(0, d.GetNumberOfPoints(), 7))
    print(ok, ok, ok)
PY
)
  check '[ $rc -eq 0 ] && [ "$got" = "True True True" ]' "mesh.attributes=on writes velocity and colour to attr.$ext ($got; $(head -c 200 "$T/err"))"
done
# render --export
"$BIN" render "$scene" --method mesh -W 32 -H 32 -q --export "$T/r.vtp" -o "$T/r.png" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/r.vtp" ] && [ -s "$T/r.png" ]' "render --method mesh --export r.vtp ($(head -c 200 "$T/err"))"
refused() { # exit 2, one line on stderr, no output
  local what=$1 out=$2; shift 2
  "$BIN" "$@" > /dev/null 2> "$T/err"; local rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && [ ! -e "$out" ]' "$what refused (rc $rc: $(head -c 200 "$T/err"))"
}
for bad in cube=0 cube=-1 smooth=median smooth_iters=-1 smooth=weigthed weights_norm=0 normal_iters=-1 attributes=maybe; do
  refused "mesh.$bad" "$T/bad.ply" mesh "$dam" -q --set "mesh.$bad" -o "$T/bad.ply"
  refused "render mesh.$bad" "$T/bad.png" render "$scene" --method mesh -W 16 -H 16 -q --set "mesh.$bad" -o "$T/bad.png"
done
refused "an unknown mesh format" "$T/x.stl" mesh "$dam" -q -o "$T/x.stl"
refused "render --export x.stl" "$T/x.stl" render "$scene" --method mesh -W 16 -H 16 -q --export "$T/x.stl" -o "$T/x.png"
refused "a folder that does not exist" "$T/no/x.ply" mesh "$dam" -q -o "$T/no/x.ply"
refused "two frames into one file" "$T/one.ply" mesh "$T/f_{}.ply" --frames 3:4 -q -o "$T/one.ply"
refused "a pattern without --frames" "$T/p.ply" mesh "$T/f_{}.ply" -q -o "$T/p_{}.ply"
refused "a mesh too large for memory" "$T/big.ply" mesh "$dam" -q --set mesh.cube=0.01 -o "$T/big.ply"
grep -q "use cube >=" "$T/err"; check '[ $? -eq 0 ]' "the memory refusal names a cube size that fits ($(cat "$T/err"))"
"$BIN" mesh "$dam" -q --set mesh.cube=0 -o "$T/bad.ply" 2> "$T/err"
check 'grep -q "cube" "$T/err" && grep -q "0.01" "$T/err"' "the refusal names the parameter and its range ($(cat "$T/err"))"
check '[ -z "$(find "$T" -name ".*.tmp*")" ]' "no temporary files left"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
