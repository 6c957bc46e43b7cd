#!/usr/bin/env bash
# Fails, listing the files, when a tracked C++ file differs from what .clang-format gives.
# Run by CTest (label lint), hence by the README's test command and CI.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
if ! command -v clang-format >/dev/null; then
    echo "check-format: clang-format is not installed (scripts/install-deps.sh installs it)" >&2
    exit 1
fi
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    echo "check-format: $root is not a git work tree; nothing to check" >&2
    exit 1
fi
bad=()
while IFS= read -r -d '' file; do
    [[ -f "$file" ]] || continue
    if ! clang-format --style=file "$file" | cmp -s - "$file"; then
        bad+=("$file")
    fi
done < <(git ls-files -z -- '*.cpp' '*.h' '*.hpp' '*.cc')
if ((${#bad[@]})); then
    echo "check-format: ${#bad[@]} file(s) differ from .clang-format; run clang-format -i on:" >&2
    printf '  %s\n' "${bad[@]}" >&2
    exit 1
fi
echo "check-format: every tracked C++ file matches .clang-format"
