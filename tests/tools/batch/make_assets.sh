#!/bin/sh
# make_assets.sh FOLDER COUNT: COUNT small, different OBJ tori (rings of U x V quads), the inputs of
# the batch tests. Every one differs in its radii and resolution.
set -eu
mkdir -p "$1"
i=0
while [ "$i" -lt "$2" ]; do
  awk -v R="$(echo "$i" | awk '{print 1 + ($1 % 7) * 0.15}')" -v r="$(echo "$i" | awk '{print 0.2 + ($1 % 5) * 0.05}')" \
    -v U=$((10 + i % 6)) -v V=$((6 + i % 3)) 'BEGIN {
    pi = 3.14159265358979
    for (i = 0; i < U; i++) for (j = 0; j < V; j++) {
      a = 2 * pi * i / U; b = 2 * pi * j / V
      printf "v %.6f %.6f %.6f\n", (R + r * cos(b)) * cos(a), (R + r * cos(b)) * sin(a), r * sin(b)
    }
    for (i = 0; i < U; i++) for (j = 0; j < V; j++) {
      i2 = (i + 1) % U; j2 = (j + 1) % V
      p = i * V + j + 1; q = i2 * V + j + 1; s = i2 * V + j2 + 1; t = i * V + j2 + 1
      printf "f %d %d %d\nf %d %d %d\n", p, q, s, p, s, t
    }
  }' >"$1/asset$(printf %03d "$i").obj"
  i=$((i + 1))
done
