// The shared tables' files in the package (tables/, the files `matc -o` writes, each with its
// .json): URLs for a page's loader. KTX2 for an engine's own loader (three's KTX2Loader); raw,
// which the engine integrations (matc/three, matc/babylon) read without a KTX2 reader.
const table = (file) => new URL(`./tables/${file}`, import.meta.url).href;
export const tableFiles = {
  ktx2: { lut: table("matc_lut.ktx2"), coefficientTable: table("matc_coefficient_table.ktx2"),
          ltc: table("matc_ltc.ktx2") },
  raw: { lut: table("matc_lut.bin"), coefficientTable: table("matc_coefficient_table.bin"),
         ltc: table("matc_ltc.bin") },
};
