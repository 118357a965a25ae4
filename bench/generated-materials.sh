# Sourced by the batch benchmarks: deterministic generated artistic materials, reflectivity in
# [0.05, 0.9) and edge tint in [0, 1) per channel, one file each (m000000.json, ...); with
# MIXED=1, every second one an F82-tint look instead (f0 and tint from the same draws), as a
# library of scanned metals beside OpenPBR looks is.
#   [MIXED=1] generate_materials DIRECTORY COUNT [SEED]
generate_materials() {
  mkdir -p "$1"
  awk -v dir="$1" -v n="$2" -v seed="${3:-12345}" -v mixed="${MIXED:-0}" 'BEGIN {
    for (i = 0; i < n; ++i) {
      for (c = 0; c < 6; ++c) { seed = (seed * 1103515245 + 12345) % 2147483648; v[c] = seed / 2147483648 }
      file = sprintf("%s/m%06d.json", dir, i)
      if (mixed && i % 2 == 1) {
        printf("{\"name\": \"m%06d\", \"f82_tint\": {\"f0\": [%.3f, %.3f, %.3f], ", i,
               0.05 + 0.85 * v[0], 0.05 + 0.85 * v[1], 0.05 + 0.85 * v[2]) > file
        printf("\"tint\": [%.3f, %.3f, %.3f]}}\n", v[3], v[4], v[5]) > file
        close(file)
        continue
      }
      printf("{\"name\": \"m%06d\", \"artistic\": {\"reflectivity\": [%.3f, %.3f, %.3f], ", i,
             0.05 + 0.85 * v[0], 0.05 + 0.85 * v[1], 0.05 + 0.85 * v[2]) > file
      printf("\"edge_tint\": [%.3f, %.3f, %.3f]}}\n", v[3], v[4], v[5]) > file
      close(file)
    }
  }'
}
