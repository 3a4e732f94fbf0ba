// The lab pool's whole layers (www/lab/tiles.js, issue 31): a result the
// page has replaced hands its layers' buffers back (LabClient.release from
// lab.js setLayers), and the next result of the same size is put together
// in them instead of fresh memory (a fresh 12 MP layer costs 100–170 ms of
// first-write page faults). Only the pool's own buffers come back, each
// once, at most four are kept, and a new photo drops them.
import assert from "node:assert/strict";
import { test } from "node:test";
import { Tiles, Whole } from "../../www/lab/tiles.js";

/** A band's answer: `layers` layers of rows [r0, r0 + rows) of a `width`-wide image, values `v`. */
function part(width, r0, rows, v, layers = 2) {
  return { layers: Array.from({ length: layers }, () => ({ width, height: rows, r0, data: new Float32Array(width * rows).fill(v) })) };
}

/** One banded result of `height` rows put together by `tiles` (two bands). */
function result(tiles, width, height, v, layers = 2) {
  const whole = new Whole(height, (T, n) => tiles.alloc(T, n));
  const half = height >> 1;
  const parts = [part(width, 0, half, v, layers), part(width, half, height - half, v, layers)];
  for (const p of parts) whole.add(p);
  return whole.result(parts, {}).layers;
}

test("a replaced result's layers carry the next result of the same size, with the next result's values", () => {
  const tiles = new Tiles(2);
  const first = result(tiles, 8, 6, 1);
  const buffers = first.map((l) => l.data.buffer);
  assert.equal(tiles.reused, 0);
  tiles.release(first);
  const second = result(tiles, 8, 6, 2);
  assert.equal(tiles.reused, 2);
  assert.deepEqual(second.map((l) => l.data.buffer), buffers);
  for (const l of second) assert.ok(l.data.every((x) => x === 2));
  // another size: fresh memory; the free ones stay for their size
  tiles.release(second);
  const other = result(tiles, 8, 7, 3);
  assert.equal(tiles.reused, 2);
  assert.ok(other.every((l) => !buffers.includes(l.data.buffer)));
  assert.equal(tiles.free.length, 2);
});

test("a buffer comes back once, only the pool's own, at most four, none after a new photo", () => {
  const tiles = new Tiles(2);
  const a = result(tiles, 4, 4, 1);
  tiles.release(a);
  tiles.release(a);
  assert.equal(tiles.free.length, 2, "released twice, kept once");
  const next = result(tiles, 4, 4, 2);
  // the same buffer never carries two layers of one result
  assert.notEqual(next[0].data.buffer, next[1].data.buffer);
  tiles.release([{ data: new Float32Array(16) }, null, {}]);
  assert.equal(tiles.free.length, 0, "a layer the pool did not make is not kept");
  for (let i = 0; i < 4; i++) tiles.release(result(tiles, 4, 4, i, 3));
  assert.ok(tiles.free.length <= 4);
  tiles.setImage(null);
  assert.equal(tiles.free.length, 0);
});
