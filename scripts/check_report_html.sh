#!/usr/bin/env bash
# Checks a report page: every image it references exists, and headless Chromium renders each
# one (no broken images). Usage: scripts/check_report_html.sh <index.html>
# Exits 0 when all images load, 1 with the list of broken images, 2 on a usage or setup error.
# Installs Debian's `chromium` with apt-get when it is missing (sudo when not root).
set -euo pipefail

die() { echo "check_report_html: $*" >&2; exit 2; }

[[ $# -eq 1 ]] || die "usage: $0 <index.html>"
page=$1
[[ -f $page ]] || die "no such file: $page"
page_dir=$(cd "$(dirname "$page")" && pwd -P)
page_abs="$page_dir/$(basename "$page")"

broken=()
declare -A missing=()

# 1. Every local image source must exist (remote and data: URLs are left to the browser).
while IFS= read -r src; do
  [[ -z $src ]] && continue
  case $src in
    data:* | http://* | https://*) continue ;;
    file://*) path=${src#file://} ;;
    /*) path=$src ;;
    *) path="$page_dir/$src" ;;
  esac
  path=${path//&amp;/&}
  path=${path//%20/ }
  if [[ ! -f $path && -z ${missing[$src]:-} ]]; then
    missing[$src]=1
    broken+=("$src (file missing)")
  fi
done < <(grep -oiE '<img[^>]*[[:space:]]src="[^"]*"' "$page_abs" | sed -E 's/.*[[:space:]][sS][rR][cC]="([^"]*)"/\1/' || true)

# 2. Render in headless Chromium and ask the page which images decoded.
if ! command -v chromium >/dev/null 2>&1; then
  echo "check_report_html: installing chromium (apt-get) ..." >&2
  as_root=()
  [[ $(id -u) -eq 0 ]] || as_root=(sudo)
  "${as_root[@]}" apt-get update -qq >&2 || die "apt-get update failed"
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends chromium >&2 ||
    die "could not install chromium"
fi

work=$(mktemp -d)
profile=$(mktemp -d)
trap 'rm -rf "$work" "$profile"' EXIT

# A copy of the page with a <base> pointing at the original folder (so relative image paths
# resolve there) and a script that writes each image's load state into the DOM.
base_href="file://${page_dir// /%20}/"
wrapper="$work/page.html"
head_tag='<[hH][eE][aA][dD]([[:space:]][^>]*)?>'
if grep -qE "$head_tag" "$page_abs"; then
  sed -E "0,/$head_tag/s||&<base href=\"$base_href\">|" "$page_abs" >"$wrapper"
else
  { echo "<base href=\"$base_href\">"; cat "$page_abs"; } >"$wrapper"
fi
cat >>"$wrapper" <<'SCRIPT'
<script>
window.addEventListener('load', function () {
  var lines = [];
  for (var i = 0; i < document.images.length; i++) {
    var im = document.images[i];
    var ok = im.complete && im.naturalWidth > 0 && im.naturalHeight > 0;
    lines.push((ok ? 'OK ' : 'BROKEN ') + im.getAttribute('src'));
  }
  var pre = document.createElement('pre');
  pre.textContent = 'SEXTANT-CHECK-BEGIN\n' + lines.join('\n') + '\nSEXTANT-CHECK-END';
  document.body.appendChild(pre);
});
</script>
SCRIPT

dom="$work/dom.html"
if ! timeout 180 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --virtual-time-budget=15000 --dump-dom "file://${wrapper// /%20}" \
  >"$dom" 2>"$work/chromium.log"; then
  tail -n 20 "$work/chromium.log" >&2
  die "chromium failed to render $page"
fi
report=$(sed -n '/SEXTANT-CHECK-BEGIN/,/SEXTANT-CHECK-END/p' "$dom")
[[ -n $report ]] || { tail -n 20 "$work/chromium.log" >&2; die "the page did not finish loading in chromium"; }

images=0
while IFS= read -r line; do
  case $line in
    OK\ *) images=$((images + 1)) ;;
    BROKEN\ *)
      images=$((images + 1))
      src=${line#BROKEN }
      [[ -n ${missing[$src]:-} ]] || broken+=("$src (does not render)")
      ;;
  esac
done <<<"$report"

if [[ ${#broken[@]} -gt 0 ]]; then
  echo "check_report_html: ${#broken[@]} broken image(s) in $page:" >&2
  printf '  %s\n' "${broken[@]}" >&2
  exit 1
fi
echo "check_report_html: $page OK ($images images render)"
