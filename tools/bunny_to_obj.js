#!/usr/bin/env node
// Converts the Stanford bunny of the npm package `bunny` (1.0.1, public domain) into a
// Wavefront OBJ (v/f records, 1-based indices, triangles only).
//
//   cd /tmp && npm pack bunny@1.0.1 && tar xzf bunny-1.0.1.tgz     # gives /tmp/package
//   node tools/bunny_to_obj.js /tmp/package assets/bunny_closed.obj
//
// The package exports { positions: [[x, y, z], ...], cells: [[i, j, k], ...] } with
// 0-based indices. Numbers are written exactly as JavaScript prints them (shortest text
// that reads back to the same double), so nothing is rounded.
'use strict';
const fs = require('fs');
const path = require('path');

if (process.argv.length !== 4) {
  console.error('usage: node bunny_to_obj.js <bunny package dir or index.js> <out.obj>');
  process.exit(2);
}
let source = path.resolve(process.argv[2]);
if (fs.statSync(source).isDirectory()) source = path.join(source, 'index.js');
const { positions, cells } = require(source);

const lines = ['# Stanford bunny, from the npm package bunny 1.0.1 (public domain)',
               '# converted by tools/bunny_to_obj.js (holefill)'];
for (const p of positions) {
  if (p.length !== 3 || !p.every(Number.isFinite)) throw new Error('bad position ' + p);
  lines.push(`v ${p[0]} ${p[1]} ${p[2]}`);
}
for (const c of cells) {
  if (c.length !== 3 || !c.every((i) => Number.isInteger(i) && i >= 0 && i < positions.length))
    throw new Error('bad cell ' + c);
  lines.push(`f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}`);
}
fs.writeFileSync(process.argv[3], lines.join('\n') + '\n');
console.log(`${process.argv[3]}: ${positions.length} vertices, ${cells.length} triangles`);
