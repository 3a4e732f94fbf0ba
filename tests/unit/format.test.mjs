// Number formatting for people (www/format.js), in Node: noise, tiny and huge
// values, integers, matrices, and differences in one direction.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import {
  agreesWithPrinted,
  denoise,
  difference,
  formatDifference,
  formatExact,
  formatNumber,
  formatValue,
  printedDecimals,
  spokenNumber,
} from "../../www/format.js";

const M = "\u2212";

describe("formatNumber", () => {
  it("drops binary noise", () => {
    assert.equal(formatNumber(0.1 + 0.2), "0.3");
    assert.equal(formatNumber(35.649122807017544), "35.6491");
    assert.equal(denoise(1 - 0.9), 0.1);
  });
  it("writes integers in full and a real minus sign", () => {
    assert.equal(formatNumber(86471658), "86471658");
    assert.equal(formatNumber(-603), `${M}603`);
    assert.equal(formatNumber(-0), "0");
  });
  it("never uses e-notation: tiny and huge values get a power of ten", () => {
    assert.equal(formatNumber(-4.440877e-6), `${M}4.44088 × 10⁻⁶`);
    assert.equal(formatNumber(0.000001877719), "1.87772 × 10⁻⁶");
    assert.equal(formatNumber(2.5e8), "250000000", "an integer is written in full");
    assert.equal(formatNumber(2.5e12 + 0.5), "2.5 × 10¹²");
    assert.equal(formatNumber(0.00042), "0.00042");
    assert.doesNotMatch(formatNumber(1e-7), /e/);
  });
  it("non-finite values", () => {
    assert.equal(formatNumber(NaN), "NaN");
    assert.equal(formatNumber(-Infinity), `${M}∞`);
  });
});

describe("formatExact beside a printed value", () => {
  it("shows two decimals more than the print", () => {
    assert.equal(formatExact(35.649122807017544, 35.37), "35.6491");
    assert.equal(formatExact(691875.63214, 691875.632), "691875.63214");
    assert.equal(formatExact(0.7752693, 0.7753), "0.775269");
  });
});

describe("matrices and vectors", () => {
  it("a matrix one row per line, a vector in brackets", () => {
    assert.equal(formatValue([[1, 0.1 + 0.2], [-2, 4e-7]]), `[1, 0.3]\n[${M}2, 4 × 10⁻⁷]`);
    assert.equal(formatValue([true, null, "north"]), "[yes, —, north]");
  });
  it("differences of arrays element by element", () => {
    assert.deepEqual(difference([[1.5, 2]], [[1, 2.5]]), [[0.5, -0.5]]);
    assert.equal(difference([1, 2], [1]), null);
  });
});

describe("differences: exact − printed, 0 within the printed precision", () => {
  it("the direction is exact − printed", () => {
    assert.equal(formatDifference(35.6491, 35.37), "+0.279");
    assert.equal(formatDifference(58.77778, 58.5), "+0.28", "one decimal more than the print");
    assert.equal(formatDifference(599.055, 603.8), `${M}4.75`);
  });
  it("within the printed rounding the difference is 0", () => {
    assert.equal(formatDifference(-4.440877e-6, 0), "0");
    assert.equal(formatDifference(75.3584 + 3.837e-13, 75.3584), "0");
    assert.ok(agreesWithPrinted(12631.58, 12632));
    assert.ok(!agreesWithPrinted(8914.438, 8891.94));
  });
  it("a small real difference keeps two significant digits", () => {
    assert.equal(formatDifference(0.6730532, 0.69), `${M}0.017`);
    assert.equal(formatDifference(1.00004, 1.00001), "+0.00003");
    // a printed value with a long tail: at most four significant digits of the difference
    assert.equal(formatDifference(0.0128724, 0.0129049490058), `${M}0.00003255`);
  });
  it("printed decimals", () => {
    assert.equal(printedDecimals(12632), 0);
    assert.equal(printedDecimals(35.37), 2);
    assert.equal(printedDecimals(0.042), 3);
    assert.equal(printedDecimals(NaN), null);
  });
});

describe("spokenNumber: powers of ten as a screen reader should say them", () => {
  it("reads formatNumber's powers of ten in words, and leaves other text alone (null)", () => {
    assert.equal(spokenNumber(formatNumber(1.87772e-6)), "1.87772 times 10 to the minus 6");
    assert.equal(spokenNumber(formatNumber(-2.5e12)), "\u22122.5 times 10 to the 12");
    assert.equal(spokenNumber("[1.2 × 10⁻¹⁰, 3 × 10¹¹]"), "[1.2 times 10 to the minus 10, 3 times 10 to the 11]");
    assert.equal(spokenNumber(formatNumber(35.649)), null);
    assert.equal(spokenNumber("2 × 3"), null);
  });
});
