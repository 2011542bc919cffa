# The unit cube, n grid squares along each edge (two triangles each, facing out), with the
# triangles whose centroid lies within r of (cx, cy, cz) cut away, as OBJ on standard output:
#   awk -v n=10 -v r=0.22 -v cx=0.5 -v cy=0 -v cz=0 -f cut_box.awk > out.obj
# The default cuts a hole across the middle of the edge along x at y = z = 0 (a 90-degree crease
# runs through it). Only the vertices of kept triangles are written.
function vertex(x, y, z,    key) {
  key = x "," y "," z
  if (!(key in ids)) {
    ids[key] = ++count
    printf "v %.6f %.6f %.6f\n", x / n, y / n, z / n
  }
  return ids[key]
}
# Corner c (0..3, counter-clockwise) of square (p, q) on the side where axis a is at s.
function corner(a, s, p, q, c,    du, dv, g) {
  du = (c == 1 || c == 2); dv = (c >= 2)
  g[a] = s; g[(a + 1) % 3] = p + du; g[(a + 2) % 3] = q + dv
  cx_[c] = g[0]; cy_[c] = g[1]; cz_[c] = g[2]
}
function triangle(i, j, k, flip,    mx, my, mz) {
  mx = (cx_[i] + cx_[j] + cx_[k]) / (3 * n) - cx
  my = (cy_[i] + cy_[j] + cy_[k]) / (3 * n) - cy
  mz = (cz_[i] + cz_[j] + cz_[k]) / (3 * n) - cz
  if (mx * mx + my * my + mz * mz < r * r) return
  if (flip) { t = j; j = k; k = t }
  faces[++nfaces] = sprintf("f %d %d %d", vertex(cx_[i], cy_[i], cz_[i]),
                            vertex(cx_[j], cy_[j], cz_[j]), vertex(cx_[k], cy_[k], cz_[k]))
}
BEGIN {
  if (n == "") n = 10
  if (r == "") r = 0.22
  if (cx == "") cx = 0.5
  for (a = 0; a < 3; a++) {
    for (side = 0; side < 2; side++) {
      s = side * n
      for (p = 0; p < n; p++) {
        for (q = 0; q < n; q++) {
          for (c = 0; c < 4; c++) corner(a, s, p, q, c)
          # (axis a+1, axis a+2, axis a) is right-handed: counter-clockwise faces +a.
          triangle(0, 1, 2, side == 0)
          triangle(0, 2, 3, side == 0)
        }
      }
    }
  }
  for (f = 1; f <= nfaces; f++) print faces[f]
}
