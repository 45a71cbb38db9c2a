// Character classes and lower-case map for src/clip/gen_unicode.py from node's ICU, as the Rust
// `tokenizers` library sees them: its regex engine (onig) knows Unicode 16.0, so the letters and
// digits that 17.0 added (node 20 ships 17.0) are given back to "other", while its lower-casing
// (Rust's char::to_lowercase) already follows 17.0. Checked against 12,000 strings tokenized by
// transformers 5.17 / tokenizers 0.23 (scripts/clip_reference.py tokenizer). Run:
//   node src/clip/gen_unicode_node.js > /tmp/classes.json
//   /usr/bin/python3 src/clip/gen_unicode.py /tmp/classes.json > src/clip/unicode_tables.h
const L = /\p{L}/u, N = /\p{N}/u, WS = /\p{White_Space}/u;
const added17 = [[0x0c5c, 0x0c5c], [0x0cdc, 0x0cdc], [0xa7ce, 0xa7cf], [0xa7d2, 0xa7d2], [0xa7d4, 0xa7d4],
  [0xa7f1, 0xa7f1], [0x10940, 0x1095f], [0x10ec5, 0x10ec7], [0x10ed0, 0x10ed8], [0x11b60, 0x11b7f],
  [0x11db0, 0x11def], [0x16ea0, 0x16edf], [0x187f8, 0x187ff], [0x18d09, 0x18d1e], [0x18d80, 0x18dff],
  [0x1e6c0, 0x1e6ff], [0x2b73a, 0x2b73f], [0x323b0, 0x3347f]];
const is17 = cp => added17.some(([a, b]) => cp >= a && cp <= b);
const starts = [], vals = [], low = [];
let cur = -1;
for (let cp = 0; cp < 0x110000; cp++) {
  let v = 0;
  if (cp < 0xd800 || cp > 0xdfff) {
    const c = String.fromCodePoint(cp);
    v = WS.test(c) ? 4 : L.test(c) ? 1 : N.test(c) ? 2 : 0;
    if (is17(cp) && v !== 4) v = 0;
    const l = c.toLowerCase();
    if (l !== c && [...l].length === 1) low.push([cp, l.codePointAt(0)]);
  }
  if (v !== cur) { starts.push(cp); vals.push(v); cur = v; }
}
console.log(JSON.stringify({version: process.versions.unicode + " minus its additions (~16.0)", starts, vals, low}));
