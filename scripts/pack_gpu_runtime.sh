#!/usr/bin/env bash
# Packs this machine's build of semsplat with the shared libraries a bare GPU image lacks (Cairo,
# FFmpeg, Cyclone DDS, assimp, cJSON, libpng, ...) and WordNet into .gl/ (ignored; carry it), so
# the whole demo (video, DDS drive) runs on the GPU machine:
#   here:  scripts/pack_gpu_runtime.sh [BUILD]            (default build/, built with CUDA)
#   there: tar -C /tmp -xJf .gl/rt.txz && tar -C /usr/share -xJf .gl/wn.txz &&
#          LD_LIBRARY_PATH=/tmp/rt/lib /tmp/rt/bin/semsplat demo --device cuda --view-size 640x480
# Libraries the GPU image (Ubuntu 24.04 + CUDA) has are left out to stay under the 64 MiB carry;
# the command there should first check `ldd /tmp/rt/bin/semsplat | grep 'not found'`.
set -eu
cd "$(dirname "$0")/.."
b=${1:-build}
[ -x "$b/semsplat" ] || { echo "no $b/semsplat: build first" >&2; exit 1; }
st=$(mktemp -d); trap 'rm -rf "$st"' EXIT
mkdir -p "$st/rt/bin" "$st/rt/lib" .gl
cp "$b/semsplat" "$st/rt/bin/"; cp "$b"/libsemsplat.so* "$st/rt/lib/"
skip='libc\.so|libm\.so|libdl|libpthread|librt\.|libstdc|libgcc_s|libcuda|libcublas|libcudart|ld-linux|linux-vdso|libcurl|libxml2|libicu|libopenblas|libgfortran|libssl|libcrypto|libz\.so|liblzma|libzstd|libkrb|libk5|libgssapi|libldap|liblber|libnghttp|libgnutls|libidn2|libunistring|libp11|libtasn|libnettle|libhogweed|libgmp|libffi|libkeyutils|libcom_err|libsasl|libpsl|librtmp|libbrotli|libresolv|libbz2|libselinux|libmount|libpcre2|libgcrypt|libgpg-error|libblkid|libgomp|libexpat|libsemsplat'
closure() { ldd "$@" 2>/dev/null | awk '/=> \//{print $3}' | sort -u | grep -vE "$skip" || true; }
for f in $(closure "$b/semsplat" "$b/libsemsplat.so"); do cp -L "$f" "$st/rt/lib/"; done
for f in $(closure "$st"/rt/lib/*.so*); do [ -f "$st/rt/lib/$(basename "$f")" ] || cp -L "$f" "$st/rt/lib/"; done
tar -C "$st" -cf - rt | xz -T2 -9e > .gl/rt.txz
[ -d /usr/share/wordnet ] && tar -C /usr/share -cf - wordnet/index.noun wordnet/data.noun wordnet/index.verb \
    wordnet/data.verb wordnet/index.adj wordnet/data.adj wordnet/index.adv wordnet/data.adv \
    $(cd /usr/share && ls wordnet/*.exc wordnet/cntlist.rev 2>/dev/null) | xz -T2 -9e > .gl/wn.txz
ls -la .gl/rt.txz .gl/wn.txz
