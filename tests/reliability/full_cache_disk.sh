#!/usr/bin/env bash
# Slow probe (issue 30, item 10): a cache root on a full 2 MiB tmpfs. Mesa maps its cache
# index, so on a full disk GL cells died of SIGBUS on every run; shaderbed must find the
# full folder first, run without the caches, pass, and say so in one note.
# Needs root (mount -t tmpfs). Usage: tests/reliability/full_cache_disk.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: full_cache_disk.sh BUILD_DIR}
shaderbed=$(realpath "$build/bin/shaderbed")
if [ "$(id -u)" -ne 0 ]; then
  echo "full_cache_disk: skipped (mounting a tmpfs needs root)"
  exit 0
fi
work=$(mktemp -d)
disk=$work/disk
mkdir -p "$disk"
cleanup() { umount "$disk" 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
mount -t tmpfs -o size=2m tmpfs "$disk"
mkdir -p "$disk/cache"
dd if=/dev/zero of="$disk/filler" bs=64k 2>/dev/null || true   # fills it: ENOSPC ends dd
for round in 1 2 3; do
  set +e
  env -u MESA_SHADER_CACHE_DIR -u MESA_SHADER_CACHE_DISABLE -u SHADERBED_MESA_SHADER_CACHE \
      -u SHADERBED_CACHE_FOLDER_NOTED SHADERBED_CACHE_DIR="$disk/cache" \
      "$shaderbed" run --case lambert,phong --variant pixel --lang glsl,hlsl --backend gl,vulkan --shape sphere \
      --size 16 --repeat 0 --quiet --json "$work/r.json" >"$work/out" 2>&1
  status=$?
  set -e
  if [ $status -ne 0 ]; then
    echo "full_cache_disk: round $round exited $status"; cat "$work/out"; exit 1
  fi
  notes=$(grep -c "shaderbed: note: the cache folder $disk/cache" "$work/out" || true)
  if [ "$notes" -ne 1 ]; then
    echo "full_cache_disk: round $round printed $notes notes, not 1"; cat "$work/out"; exit 1
  fi
  if grep -q '"status": *"error"' "$work/r.json"; then
    echo "full_cache_disk: round $round has error cells"; cat "$work/out"; exit 1
  fi
done
# With room again (the filler gone, but still under the 16 MiB margin) the caches stay off.
rm -f "$disk/filler"
"$shaderbed" --cache-dir "$disk/cache" run --case lambert --variant pixel --lang glsl --backend gl --shape sphere \
    --size 16 --repeat 0 --quiet >"$work/out" 2>&1
grep -q "under the 16 MiB a cache needs" "$work/out" || { echo "full_cache_disk: no margin note"; cat "$work/out"; exit 1; }
echo "full_cache_disk: ok (3 runs on a full cache disk passed with one note each)"
