#!/usr/bin/env bash
# Installs what snell's build, tests and examples need on Debian 12, if missing.
# Run as root (or with sudo). Debian packages with apt-get, the WebGPU
# runtime's npm packages (Deno, naga, dawn.node) from tools/webgpu's committed
# lockfile, three.js from examples/web's and the glTF tools from tools/gltf's;
# nothing is downloaded otherwise.
set -euo pipefail
packages=(
  cmake g++ make pkg-config
  libglm-dev                      # the core's only dependency
  libgtest-dev libbenchmark-dev   # tests and benchmarks
  glslang-tools spirv-tools spirv-cross  # offline GLSL/HLSL compilation checks
  libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev  # Mesa llvmpipe, no GPU needed
  libvulkan-dev mesa-vulkan-drivers  # the Vulkan loader and lavapipe (Vulkan on the CPU): the Vulkan parity runs
  libembree-dev nlohmann-json3-dev libtinyobjloader-dev libtinygltf-dev libstb-dev libcli11-dev  # the lab
  libspng-dev libjpeg62-turbo-dev libopenexr-dev  # the lab's image decoders (PNG, JPEG, OpenEXR)
  clang-14 libclang-rt-14-dev valgrind  # libFuzzer targets (tests/fuzz), the GPU leak check
  apngasm                         # the gallery's animated PNGs (scripts/gallery.sh)
  chromium                        # headless: the WebGL 2 parity runs (SwiftShader, no GPU)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js and npm install the WebGPU runtime's packages and three.js, and serve the browser pages (any
# Node.js that has npm: Debian's, or one that bundles npm).
command -v npm > /dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -eq 0 ]; then
  echo "snell: all build dependencies are installed"
else
  if [ "$(id -u)" -ne 0 ]; then
    echo "snell: missing packages: ${missing[*]}" >&2
    echo "snell: run this script as root (sudo bash scripts/install-deps.sh)" >&2
    exit 1
  fi
  echo "snell: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The WebGPU parity runtime: Deno (its WebGPU runs WGSL on lavapipe) and naga (SPIR-V to WGSL), pinned
# by tools/webgpu/package-lock.json; again whenever the lockfile changed since the last install.
webgpu="$(cd "$(dirname "$0")/.." && pwd)/tools/webgpu"
if [ ! -f "$webgpu/node_modules/.package-lock.json" ] || [ "$webgpu/package-lock.json" -nt "$webgpu/node_modules/.package-lock.json" ]; then
  echo "snell: installing the WebGPU runtime's npm packages (tools/webgpu)"
  npm ci --prefix "$webgpu" --no-audit --no-fund --loglevel=error
fi
# three.js for the web example's page (examples/web), pinned by its package-lock.json, the same way.
web="$(cd "$(dirname "$0")/.." && pwd)/examples/web"
if [ ! -f "$web/node_modules/.package-lock.json" ] || [ "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; then
  echo "snell: installing the web example's npm packages (examples/web: three.js)"
  npm ci --prefix "$web" --no-audit --no-fund --loglevel=error
fi
# The glTF tools (tools/gltf: the Khronos validator run on the bundled assets in the tests, and
# glTF-Transform, which wrote them), pinned by tools/gltf/package-lock.json, the same way.
gltf="$(cd "$(dirname "$0")/.." && pwd)/tools/gltf"
if [ ! -f "$gltf/node_modules/.package-lock.json" ] || [ "$gltf/package-lock.json" -nt "$gltf/node_modules/.package-lock.json" ]; then
  echo "snell: installing the glTF tools' npm packages (tools/gltf: gltf-validator, glTF-Transform)"
  npm ci --prefix "$gltf" --no-audit --no-fund --loglevel=error
fi
