# Sourced by run_fuzzers.sh and campaign.sh: the fuzz targets, the source each
# is built from (tests/fuzz/fuzz_<source>.cpp) and the seed corpus each starts
# from (tests/fuzz/corpus/<corpus>/).
# shellcheck shell=bash
snell_fuzz_targets="include_flattener scene scene_render obj gltf image_png image_jpeg image_exr image_hdr"
# scene_render renders what the scene corpus loads; every other target has its own.
corpus_of() { case $1 in scene_render) echo scene ;; *) echo "$1" ;; esac; }
# The image_<format> targets are one source, fuzz_image.cpp, each fuzzed from its own format's corpus.
source_of() { case $1 in image_*) echo image ;; *) echo "$1" ;; esac; }
# The dictionary libFuzzer inserts whole (-dict), for the targets that have one.
dict_of() { case $1 in scene|scene_render) echo "-dict=$root/tests/fuzz/dictionaries/scene.dict" ;; esac; }
