# A UV sphere (unit radius, z stretched by `stretch`) with the faces between two latitudes cut
# away, as OBJ on standard output: the cap north of the cut stays as a separate piece.
#   awk -v rows=40 -v cols=64 -v from=6 -v to=12 -v stretch=1 -f cut_sphere.awk > out.obj
# Face rows from..to-1 are cut (row 0 touches the north pole). A wide band around a small cap
# leaves an island inside the southern part's hole; a band on the equator of a stretched sphere
# leaves two facing loops of the same size, a gap to bridge. Vertex rows inside the band are left
# out, so every vertex is used.
function kept(i) { return i <= from || i >= to }
function id(i, j) {
  if (i == 0) return 1
  if (i == rows) return count
  return index_of[i] + (j % cols)
}
BEGIN {
  pi = atan2(0, -1)
  count = 0
  for (i = 0; i <= rows; i++) {
    if (!kept(i)) continue
    index_of[i] = count + 1
    theta = pi * i / rows
    n = (i == 0 || i == rows) ? 1 : cols
    for (j = 0; j < n; j++) {
      phi = 2 * pi * j / cols
      printf "v %.6f %.6f %.6f\n", sin(theta) * cos(phi), sin(theta) * sin(phi), stretch * cos(theta)
      count++
    }
  }
  for (i = 0; i < rows; i++) {
    if (i >= from && i < to) continue
    for (j = 0; j < cols; j++) {
      a = id(i, j); b = id(i + 1, j); c = id(i + 1, j + 1); d = id(i, j + 1)
      if (i == 0) print "f", a, b, c
      else if (i == rows - 1) print "f", a, b, d
      else { print "f", a, b, c; print "f", a, c, d }
    }
  }
}
