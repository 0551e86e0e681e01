# Sourced by experiments/gpu/{run,device,check}.sh (from the repository root): the GL
# environment of a bare GPU node.
# shellcheck shell=bash

# glvnd finds NVIDIA's EGL through its vendor file, which a bare node may keep off the
# default path (the driver mounted under /usr/local/nvidia)
node_gl_env() {
  local nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f $nv ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
  return 0
}

# The GL loaders carried as Debian packages in .gl/ (glvnd's libEGL, libGLdispatch, ...),
# unpacked into / for the driver's own libraries to find (the pack's copies serve only
# fluidsurf's binaries, through their rpath). Only on a machine with nvidia-smi, as root:
# never over this machine's libraries.
node_unpack_loaders() {
  command -v nvidia-smi > /dev/null && compgen -G '.gl/*.deb' > /dev/null || return 0
  local f
  for f in .gl/*.deb; do dpkg -x "$f" / || echo "node_env: cannot unpack $f (root needed)" >&2; done
  ldconfig
}
