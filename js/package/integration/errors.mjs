// The version of matc's outputs the engine integrations read, and the error they stop with.
// The matc version whose outputs this code reads (matc_version in the manifest).
export const kMatcVersion = "0.1.0";

// Text from an input or an argument, quoted for a message: escaped as a JSON string (no control
// byte or line break reaches the console) and cut after 64 characters, with its length.
export function quoted(text) {
  const whole = String(text);
  if (whole.length <= 64) return JSON.stringify(whole);
  return `${JSON.stringify(whole.slice(0, 64))}... (${whole.length} characters)`;
}

// A problem that must stop the material from being used: reported on the console and thrown.
export class MatcWebError extends Error {
  constructor(message) {
    super(`matc: ${message}`);
    this.name = "MatcWebError";
    console.error(this.message);
  }
}
