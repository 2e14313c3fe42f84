#!/bin/bash
# `make package`'s Debian packages, checked as a user would meet them: built by CPack from
# the build tree, their Depends covering every shared library the executables load
# (dpkg's own database says which package ships each), unpacked into a fresh root
# (dpkg -x), and run from there: vesica --version and a small pipeline (a pouch surface,
# its wall mesh, a filling), then an outside project built against the unpacked vesica-dev.
# Usage: debian_package.sh SOURCE_DIR BUILD_DIR WORK_DIR VERSION [GENERATOR]
set -euo pipefail
source=$1 build=$2 work=$3 version=$4 generator=${5:-Ninja}
rm -rf "$work"
mkdir -p "$work/pkg" "$work/root" "$work/run"

cpack --config "$build/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 ||
  { tail -30 "$work/cpack.log"; exit 1; }
deb=$work/pkg/vesica_${version}_amd64.deb
dev=$work/pkg/vesica-dev_${version}_amd64.deb
test -s "$deb" && test -s "$dev" || { ls "$work/pkg"; echo "no vesica_${version}_amd64.deb"; exit 1; }

# Depends: every package that ships a library the executables need (NEEDED entries).
depends=$(dpkg-deb -f "$deb" Depends)
depended=$(sed 's/([^)]*)//g; s/[,|]/ /g' <<<"$depends")  # the package names alone
dpkg -x "$deb" "$work/root"
missing=""
# Every NEEDED library of every executable, as "exe lib path" lines (path as ldd resolves it).
needed=$(for exe in "$work"/root/usr/bin/*; do
  loaded=$(ldd "$exe")
  for lib in $(readelf -d "$exe" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    path=$(awk -v l="$lib" '$1 == l {print $3}' <<<"$loaded")
    # The dynamic loader (NEEDED where position-independent code reads thread-locals
    # through __tls_get_addr): ldd shows it by its own path, without "=>".
    [ -n "$path" ] || path=$(awk -v l="$lib" '$1 ~ "/" l "$" {print $1}' <<<"$loaded")
    echo "$exe $lib ${path:-?}"
  done
done)
if grep -q ' ?$' <<<"$needed"; then grep ' ?$' <<<"$needed" | sed 's/ ?$/ not found/'; exit 1; fi
# Which package ships each library: one dpkg -S for all of them (each call reads the whole
# package database), under each name the file may be listed by (/lib or /usr/lib, a link).
declare -A owner_of names_of
candidates=$(awk '{print $3}' <<<"$needed" | sort -u | while read -r path; do
  echo "$path"; readlink -f "$path"; echo "${path#/usr}"; done | sort -u)
while IFS= read -r line; do
  owner_of[${line#*: }]=${line%%: *}
done < <(dpkg -S $candidates 2>/dev/null | grep -v '^diversion' || true)
while read -r exe lib path; do
  owner=${owner_of[$path]:-${owner_of[$(readlink -f "$path")]:-${owner_of[${path#/usr}]:-}}}
  pkg=${owner%%[:,]*}
  [ -n "$pkg" ] || { echo "$path: no Debian package ships it"; exit 1; }
  # The package itself or a name it provides (libspdlog1.10 provides libspdlog1.10-fmt9).
  if [ -z "${names_of[$pkg]+set}" ]; then
    names_of[$pkg]=" $pkg $(dpkg-query -W -f='${Provides}' "$pkg" | sed 's/([^)]*)//g; s/,/ /g') "
  fi
  found=no
  for name in $depended; do
    [[ "${names_of[$pkg]}" == *" $name "* ]] && found=yes
  done
  [ $found = yes ] || missing="$missing $pkg($lib)"
done <<<"$needed"
[ -z "$missing" ] || { echo "Depends lacks:$missing"; echo "Depends: $depends"; exit 1; }
echo "Depends: $(tr ',' '\n' <<<"$depends" | grep -c .) packages, covering every NEEDED library"

# Run from the unpacked root, with nothing of the build tree reachable.
bin=$work/root/usr/bin
[ "$(env -i PATH=/usr/bin:/bin "$bin/vesica" --version)" = "vesica $version" ] ||
  { echo "vesica --version: $(env -i PATH=/usr/bin:/bin "$bin/vesica" --version)"; exit 1; }
cat >"$work/run/tiny.yaml" <<'YAML'
pipeline: tiny
workdir: out
stages:
  surface:  {output: pouch.vtp, params: {shape: pouch, volume_ml: 100, elongation: 1.5, edge_mm: 8}}
  mesh:     {input: pouch.vtp, output: pouch.msh, params: {thickness_mm: 3}}
  simulate: {input: pouch.msh, output: sim,
             params: {mu_kpa: 3, residual_ml: 100, start_ml: 100, capacity_ml: 150, no_void: true,
                      no_series: true}}
YAML
(cd "$work/run" && env -i PATH=/usr/bin:/bin HOME="$work/run" "$bin/vesica" run tiny.yaml \
  --json >run.json) || { cat "$work/run/run.json"; exit 1; }
test -s "$work/run/out/sim/history.csv" || { echo "no history.csv"; exit 1; }
echo "tiny pipeline from the package: $(grep -c . "$work/run/out/sim/history.csv") history rows"

# vesica-dev: the CMake package, relocated into the fresh root, builds an outside project.
dpkg -x "$dev" "$work/root"
"$source/tests/install/outside_project.sh" "$source" "$work/root/usr" "$work/outside" "$generator"
