#!/usr/bin/env bash
# Runs a command and prints its output as a fenced Markdown code block (for generated doc blocks).
set -euo pipefail
echo '```text'
"$@"
echo '```'
