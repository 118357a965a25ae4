// The version of matc's outputs the engine integrations read, and the error they stop with.
// The matc version whose outputs this code reads (matc_version in the manifest).
export const kMatcVersion = "0.1.0";

// A problem that must stop the material from being used: reported on the console and thrown.
export class MatcWebError extends Error {
  constructor(message) {
    super(`matc: ${message}`);
    this.name = "MatcWebError";
    console.error(this.message);
  }
}
