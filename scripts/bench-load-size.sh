#!/usr/bin/env bash
# Loading time of a large mesh, Caustica against pbrt-v4: a binary PLY of TRIANGLES triangles
# (default 5 million: a rippled height field of n x n vertices) under one area light, rendered at
# 1 sample per pixel and 64 x 64 pixels on 2 threads, so that the wall time is loading (parsing,
# the PLY, building the BVH) plus a negligible render. The two renderers take turns, REPETITIONS
# times (default 3), and the table gives each one's median wall time and the ratio.
# Not part of CI: it needs pbrt-v4 (PBRT, default ../shared/tools/pbrt-v4/pbrt) and a built
# caustica (CAUSTICA, default build/caustica).
#
# Usage: scripts/bench-load-size.sh [TRIANGLES]
set -euo pipefail
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
PBRT=$(realpath "${PBRT:-$root/../shared/tools/pbrt-v4/pbrt}")
CAUSTICA=$(realpath "${CAUSTICA:-$root/build/caustica}")
REPETITIONS=${REPETITIONS:-3}
triangles=${1:-5000000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

count=$(python3 - "$triangles" "$tmp/mesh.ply" <<'EOF'
import array, math, struct, sys
triangles, path = int(sys.argv[1]), sys.argv[2]
n = math.isqrt(triangles // 2) + 1  # n x n vertices make 2 (n - 1)^2 triangles
xy = [2 * i / (n - 1) - 1 for i in range(n)]
vertices = array.array('f')
for y in xy:
    for x in xy:
        vertices.extend((x, y, 0.02 * math.sin(40 * x) * math.cos(40 * y)))
count = 2 * (n - 1) ** 2
face = struct.Struct('<B3i')  # the vertex count, then three indices
faces = bytearray(face.size * count)
k = 0
for j in range(n - 1):
    for i in range(n - 1):
        a = j * n + i
        face.pack_into(faces, k, 3, a, a + 1, a + n + 1)
        face.pack_into(faces, k + face.size, 3, a, a + n + 1, a + n)
        k += 2 * face.size
with open(path, 'wb') as f:
    f.write(('ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n'
             'property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n'
             % (n * n, count)).encode())
    f.write(vertices.tobytes())
    f.write(faces)
print(count)
EOF
)

cat > "$tmp/scene.pbrt" <<EOF
LookAt 0 -2.5 2  0 0 0  0 0 1
Camera "perspective" "float fov" [ 40 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ] "string filename" [ "out.exr" ]
Sampler "independent" "integer pixelsamples" [ 1 ]
Integrator "path"
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 10 10 10 ]
  Translate 0 0 3
  ReverseOrientation
  Shape "disk" "float radius" [ 0.5 ]
AttributeEnd
Material "diffuse"
Shape "plymesh" "string filename" [ "mesh.ply" ]
EOF

cd "$tmp"
now() { date +%s.%N; }
for ((r = 1; r <= REPETITIONS; ++r)); do
    start=$(now)
    "$PBRT" --quiet --nthreads 2 --outfile pbrt.exr scene.pbrt > /dev/null 2>&1
    echo "pbrt-v4 $(echo "$(now) - $start" | bc -l)"
    start=$(now)
    "$CAUSTICA" render scene.pbrt --threads 2 --quiet -o caustica.exr > /dev/null 2>&1
    echo "caustica $(echo "$(now) - $start" | bc -l)"
done > runs.txt
median() { awk -v l="$1" '$1 == l {print $2}' runs.txt | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
p=$(median pbrt-v4)
c=$(median caustica)
echo "| triangles | pbrt-v4 s | Caustica s | Caustica / pbrt-v4 |"
echo "| --- | --- | --- | --- |"
printf "| %d | %.2f | %.2f | %.2f |\n" "$count" "$p" "$c" "$(echo "$c / $p" | bc -l)"
