// A textured glTF metal's F0 table (MATC_materials_fresnel's f0Table, docs/gltf.md): its check
// and its texels as the float texture matc's shader library reads.
import { checkedFiniteRows } from "./coefficient-rows.mjs";
import { MatcWebError } from "./errors.mjs";

// The entries of an F0 table (MATC_materials_fresnel's f0Table, docs/gltf.md): entry i is the metal
// compiled at F0 = (i / (kF0TableEntries - 1))^4.
export const kF0TableEntries = 33;

// An F0 table ({ coefficients, underCoatCoefficients: kF0TableEntries entries of 3 rows of c_0..c_3;
// the latter only under a coat, `coated`}), or an error naming `what`.
export function checkedF0Table(table, coated, what) {
  const entries = (value, field) => {
    if (!Array.isArray(value) || value.length !== kF0TableEntries) {
      throw new MatcWebError(`${what}.${field} must be ${kF0TableEntries} entries of 3 rows of 4 numbers`);
    }
    for (const entry of value) checkedFiniteRows(entry, what, field);
  };
  entries(table?.coefficients, "coefficients");
  if (coated !== (table.underCoatCoefficients !== undefined)) {
    throw new MatcWebError(`${what}: ${coated ? "a coated metal's table needs" : "a bare metal's table has no"} ` +
                           "underCoatCoefficients");
  }
  if (coated) entries(table.underCoatCoefficients, "underCoatCoefficients");
  return table;
}

// An F0 table as the texels of an RGBA float texture of kF0TableEntries x 6, row-major (texel
// (i, c) entry i's row of channel c in air, (i, 3 + c) under the coat; zero for a bare metal), as
// matc's MATC_COEFFICIENTS_FROM_F0_TABLE and MATC_UNDER_COAT_FROM_F0_TABLE read it.
export function f0TableTexels(table) {
  const texels = new Float32Array(kF0TableEntries * 6 * 4);
  const put = (entries, firstRow) => entries?.forEach((rows, i) => rows.forEach((row, channel) => {
    texels.set(row, ((firstRow + channel) * kF0TableEntries + i) * 4);
  }));
  put(table.coefficients, 0);
  put(table.underCoatCoefficients, 3);
  return texels;
}
