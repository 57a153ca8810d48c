// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decodes LAZ files with laz-perf (an independent LASzip implementation, npm) and compares their
// records with those of uncompressed LAS files: each argument pair LAZ=LAS. Prints one line per
// pair and "laz-perf-ok" when every pair holds the same records.
// usage: node laz_perf_check.js NODE_MODULES_DIR A.laz=A.las ...
'use strict';
const fs = require('fs');
const path = require('path');
const { createLazPerf } = require(path.resolve(process.argv[2], 'laz-perf'));

function lasRecords(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const start = view.getUint32(96, true);
  const length = view.getUint16(105, true);
  const minor = bytes[25];
  const count = minor >= 4 ? Number(view.getBigUint64(247, true)) : view.getUint32(107, true);
  return { records: bytes.subarray(start, start + count * length), length, count };
}

(async () => {
  const LazPerf = await createLazPerf();
  let failed = false;
  for (const pair of process.argv.slice(3)) {
    const [laz, las] = pair.split('=');
    const compressed = fs.readFileSync(laz);
    const expected = lasRecords(fs.readFileSync(las));
    const file = LazPerf._malloc(compressed.length);
    LazPerf.HEAPU8.set(compressed, file);
    const reader = new LazPerf.LASZip();
    reader.open(file, compressed.length);
    const count = reader.getCount(), length = reader.getPointLength();
    const point = LazPerf._malloc(length);
    let same = count === expected.count && length === expected.length;
    for (let i = 0; same && i < count; ++i) {
      reader.getPoint(point);
      const decoded = LazPerf.HEAPU8.subarray(point, point + length);
      const record = expected.records.subarray(i * length, (i + 1) * length);
      for (let b = 0; b < length; ++b)
        if (decoded[b] !== record[b]) { same = false; console.log(`${laz}: record ${i} byte ${b} differs`); break; }
    }
    reader.delete();
    LazPerf._free(point);
    LazPerf._free(file);
    console.log(`${laz}: ${count} records of ${length} bytes, ${same ? 'the same as' : 'NOT the same as'} ${las}'s`);
    failed = failed || !same;
  }
  if (!failed)
    console.log('laz-perf-ok');
  process.exit(failed ? 1 : 0);
})().catch((e) => { console.error(e.message || e); process.exit(1); });
