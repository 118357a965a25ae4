// Counts checks and ends with the plain "N passed, N failed" line the CI reads.
let passed = 0;
let failed = 0;

export function check(ok, message) {
  if (ok) {
    passed += 1;
  } else {
    failed += 1;
    console.log(`FAIL ${message}`);
  }
}

export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed === 0 ? 0 : 1);
}
