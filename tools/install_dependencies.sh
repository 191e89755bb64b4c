#!/usr/bin/env bash
# Installs the Debian 12 packages Temporal Styles needs, if any is missing (apt-get; sudo when not root).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libgtest-dev
  libegl-dev libegl1-mesa-dev libgl1-mesa-dri libosmesa6-dev
  libopenimageio-dev openimageio-tools glslang-tools
  libglfw3-dev libimgui-dev xvfb xauth
  libnetcdf-dev libnifti2-dev zlib1g-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libfreetype-dev fonts-dejavu-core
  pybind11-dev python3-dev python3-numpy python3-xarray python3-netcdf4 python3-pytest
  libopenmpi-dev openmpi-bin
  libtiff-dev libpugixml-dev libblosc-dev libzstd-dev liblz4-dev liblzma-dev libgdcm-dev
  python3-tifffile python3-zarr python3-pydicom python3-vtk9 dcmtk
  desktop-file-utils shared-mime-info libxml2-utils dpkg-dev lintian libx11-dev
  python3-skbuild python3-build python3-venv python3-pip python3-wheel
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install_dependencies: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_dependencies: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
