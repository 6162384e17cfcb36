#!/usr/bin/env bash
# Measures every chapter on a machine with a GPU but no Rust toolchain (a
# lent machine), saving what the bench printed, raw; `cargo xtask bench saved`
# turns the saved files into the book's tables here. It runs what
# `cargo xtask bench` and `cargo xtask bench sizes` run, from one binary.
#
# Here, in the repository root:
#   cargo build --release -p course --example every_chapter
#   mkdir -p .gpubench && strip -o .gpubench/every_chapter target/release/examples/every_chapter
#   xz -9 -f .gpubench/every_chapter          # what may travel to a lent machine is small
#   mkdir -p .gl && (cd .gl && apt-get download libvulkan1 libegl1 libgl1 libgles2 libglvnd0 libglx0 libopengl0)
#     (the loader libraries wgpu opens, for a machine that has the GPU's driver but not them)
# There, in a copy of the repository root carrying `.gpubench` and `.gl`
# (both ignored by git), with OUT naming an empty folder:
#   OUT=/some/folder bash xtask/gpu-bench.sh
# Back here, with OUT's files in book/src/bench/gpu/raw/:
#   cargo xtask bench saved book/src/bench/gpu/raw book/src/bench/gpu
#
# OUT receives gpu.txt (the GPU, the thread count, the CPU), sizes.txt (each
# chapter's first view at the seeds' sizes, each run after a
# `=== CHAPTER VIEW WxH` line) and CHAPTER.txt (`CHAPTER --bench --size
# 1280x720`, then the `time` of the run). The files in book/src/bench/gpu/raw/
# came from this script, run with OUT=/tmp/o and the folder brought back
# as a tarball (a lent machine returns at most 8 files).
set -u
: "${OUT:?set OUT to the folder the results go to}"
mkdir -p "$OUT"

# The loaders, unpacked over the root (no package manager run), and the
# NVIDIA driver's Vulkan manifest where a container keeps it apart.
if compgen -G ".gl/*.deb" > /dev/null; then
  for deb in .gl/*.deb; do dpkg -x "$deb" /; done
  ldconfig
fi
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -f "$nvidia_icd" ]; then export VK_DRIVER_FILES=$nvidia_icd; fi
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}

# One binary for every chapter: linked under a chapter's name, it is that chapter.
bin=$(mktemp -d)
xz -dc .gpubench/every_chapter.xz > "$bin/every_chapter"
chmod +x "$bin/every_chapter"
chapters=$("$bin/every_chapter" --list-chapters) || exit 1
for chapter in $chapters; do ln -sf every_chapter "$bin/$chapter"; done

{ nvidia-smi -L; nproc; grep -m1 "model name" /proc/cpuinfo; } > "$OUT/gpu.txt"
cat "$OUT/gpu.txt"

: > "$OUT/sizes.txt"
for chapter in $chapters; do
  view=$("$bin/$chapter" --list-views | head -1 | awk '{print $1}')
  for size in 1280x720 1920x1080 2560x1440; do
    echo "=== $chapter $view $size" >> "$OUT/sizes.txt"
    timeout 30 "$bin/$chapter" --bench --frames 10 --view "$view" --size "$size" >> "$OUT/sizes.txt" 2>&1
  done
done
echo "sizes done"

for chapter in $chapters; do
  ( time timeout 60 "$bin/$chapter" --bench --size 1280x720 ) > "$OUT/$chapter.txt" 2>&1
  echo "$chapter done $(date +%T)"
done
