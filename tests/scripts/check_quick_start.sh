#!/usr/bin/env bash
# The README's quick start, as a newcomer would run it: its shell lines (with build/matc replaced
# by the binary under test) in a scratch folder, then its GLSL lines in a fragment shader (the
# #include lines replaced by the files they name) through the glslangValidator CLI.
# Usage: check_quick_start.sh MATC README
set -euo pipefail
matc=$1
readme=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The fenced blocks between the markers: sh lines, then glsl lines.
block() {  # language
  sed -n '/<!-- BEGIN QUICK START/,/<!-- END QUICK START -->/p' "$readme" |
    sed -n "/^\`\`\`$1\$/,/^\`\`\`\$/p" | sed '1d;$d'
}
block sh >"$work/quick_start.sh"
block glsl >"$work/quick_start.glsl"
if [ ! -s "$work/quick_start.sh" ] || [ ! -s "$work/quick_start.glsl" ]; then
  echo "FAIL: README.md has no quick start between its markers" >&2
  exit 1
fi

cd "$work"
sed -e "s|build/matc|$matc|g" -e 's/  *#.*$//' quick_start.sh >run.sh
bash -euo pipefail run.sh

{
  echo "#version 450"
  while IFS= read -r line; do
    if [[ $line =~ ^#include\ \"([^\"]+)\" ]]; then
      cat "out/${BASH_REMATCH[1]}"
    fi
  done <quick_start.glsl
  echo "layout(location = 0) out vec4 colour;"
  echo "void main() {"
  echo "  float VdotH = gl_FragCoord.x;"
  grep -v '^#include' quick_start.glsl
  echo "  colour = vec4(F, 1.0);"
  echo "}"
} >quick_start.frag
glslangValidator quick_start.frag >log 2>&1 || {
  cat log
  echo "FAIL: the quick start's GLSL does not compile" >&2
  exit 1
}
echo "quick start: matc wrote $(ls out | wc -l) files; its GLSL compiles"
