#!/usr/bin/env bash
# Prints an OBJ disk for the shell tests: a 60 x 60 grid (6962 triangles) on
# a bumpy height field.
awk 'BEGIN {
  n = 60
  for (j = 0; j < n; ++j) for (i = 0; i < n; ++i)
    printf "v %.6f %.6f %.6f\n", i / (n - 1), j / (n - 1), 0.2 * sin(6 * i / n) * cos(5 * j / n)
  for (j = 0; j < n - 1; ++j) for (i = 0; i < n - 1; ++i) {
    a = j * n + i + 1; b = a + 1; c = a + n; d = c + 1
    printf "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c
  }
}'
