// Writes the mesh of the npm package `bunny` (1.0.1) as ASCII PLY on standard output.
// Usage: npm pack bunny && tar xzf bunny-1.0.1.tgz && node convert.js package > bunny.ply
const path = require("path");
const bunny = require(path.resolve(process.argv[2] || "package"));
const lines = [
  "ply",
  "format ascii 1.0",
  "comment Stanford bunny, from the npm package bunny 1.0.1 (see ATTRIBUTION.md)",
  `element vertex ${bunny.positions.length}`,
  "property float x",
  "property float y",
  "property float z",
  `element face ${bunny.cells.length}`,
  "property list uchar int vertex_indices",
  "end_header",
];
for (const p of bunny.positions) lines.push(p.join(" "));
for (const c of bunny.cells) lines.push(`3 ${c.join(" ")}`);
process.stdout.write(lines.join("\n") + "\n");
