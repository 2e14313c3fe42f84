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
for exe in "$work"/root/usr/bin/*; do
  for lib in $(readelf -d "$exe" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    path=$(ldd "$exe" | awk -v l="$lib" '$1 == l {print $3}')
    # The dynamic loader (NEEDED where position-independent code reads thread-locals
    # through __tls_get_addr): ldd shows it by its own path, without "=>".
    [ -n "$path" ] || path=$(ldd "$exe" | awk -v l="$lib" '$1 ~ "/" l "$" {print $1}')
    [ -n "$path" ] || { echo "$exe: $lib not found"; exit 1; }
    owner=$(dpkg -S "$path" 2>/dev/null || dpkg -S "$(readlink -f "$path")" 2>/dev/null ||
            dpkg -S "${path#/usr}" 2>/dev/null || true)
    pkg=${owner%%:*}
    [ -n "$pkg" ] || { echo "$path: no Debian package ships it"; exit 1; }
    # The package itself or a name it provides (libspdlog1.10 provides libspdlog1.10-fmt9).
    names=" $pkg $(dpkg-query -W -f='${Provides}' "$pkg" | sed 's/([^)]*)//g; s/,/ /g') "
    found=no
    for name in $depended; do
      [[ "$names" == *" $name "* ]] && found=yes
    done
    [ $found = yes ] || missing="$missing $pkg($lib)"
  done
done
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
