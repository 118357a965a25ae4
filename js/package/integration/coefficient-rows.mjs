// Coefficient rows (R, G, B: c_0..c_3) as the integrations read them from a build directory, a
// glTF extension or a source of useMatcFresnel, each checked before a shader gets it.
import { MatcWebError } from "./errors.mjs";

// A compiled material's coefficient rows (R, G, B: c_0..c_3), or an error naming `field` of `file`.
export function checkedRows(rows, file, field) {
  if (!Array.isArray(rows) || rows.length !== 3 || rows.some((row) => row.length !== 4)) {
    throw new MatcWebError(`${file}: ${field} must be 3 rows of 4 numbers`);
  }
  return rows;
}

// Whether every value of coefficient rows is a finite number.
export const finiteRows = (rows) => rows.every((row) => row.every((value) => typeof value === "number" && Number.isFinite(value)));

// Coefficient rows (checkedRows) of finite numbers, or an error naming `what`.`field`.
export function checkedFiniteRows(rows, what, field) {
  checkedRows(rows, what, field);
  if (!finiteRows(rows)) throw new MatcWebError(`${what}.${field} must be finite numbers`);
  return rows;
}

// Coefficient rows of a Schlick curve at F0 = 0 (c_0 = 0, c_1 = 1 per channel, finite c_2, c_3),
// or an error naming `what`.
export function checkedZeroF0Rows(rows, what) {
  checkedRows(rows, what, "zeroF0Coefficients");
  if (!finiteRows(rows) || rows.some((row) => row[0] !== 0 || row[1] !== 1)) {
    throw new MatcWebError(`${what}: zeroF0Coefficients must be rows [0, 1, c_2, c_3] of finite numbers`);
  }
  return rows;
}
