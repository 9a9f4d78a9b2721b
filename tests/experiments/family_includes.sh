#!/bin/sh
# The rule of experiments/src/kinds/: a family folder (registration/, plane_slam/, …) includes only
# kit/, the framework (sextant/experiments/…) and the libraries, never a file of another family;
# kit/ includes no family. Every quoted #include is resolved as the compiler does (beside the file,
# then below src/kinds/); each one that lands in another family's folder is named with file and
# line, and the test fails.
#   family_includes.sh <experiments/src/kinds>
kinds=$(realpath "$1") || exit 2
[ -d "$kinds/kit" ] || { echo "no kit/ below $kinds"; exit 2; }

violations=$(
  for dir in "$kinds"/*/; do
    family=$(basename "$dir")
    find "$dir" \( -name '*.cpp' -o -name '*.hpp' \) | sort | while IFS= read -r file; do
      grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" | while IFS= read -r hit; do
        line=${hit%%:*}
        target=$(printf '%s\n' "$hit" | sed 's/^[^"]*"\([^"]*\)".*/\1/')
        if [ -f "$(dirname "$file")/$target" ]; then
          resolved=$(realpath "$(dirname "$file")/$target")
        elif [ -f "$kinds/$target" ]; then
          resolved=$(realpath "$kinds/$target")
        else
          continue  # the framework or a library
        fi
        below=${resolved#"$kinds"/}
        case $below in
          */*) owner=${below%%/*} ;;
          *) continue ;;  # a file directly in src/kinds/: framework
        esac
        [ "$owner" = "$family" ] || [ "$owner" = kit ] && continue
        echo "${file#"$kinds"/}:$line: the $family family includes \"$target\", a file of the $owner family" \
             "(share it through kit/ instead)"
      done
    done
  done
)

if [ -n "$violations" ]; then
  printf '%s\n' "$violations"
  exit 1
fi
echo "every family of $kinds includes only kit/, the framework and the libraries"
