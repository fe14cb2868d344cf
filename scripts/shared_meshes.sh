# Sourced by the scripts that run the program on the shared meshes, from the
# repository's root: AKVF (the program) and DATA (the meshes), each checked.
AKVF=./build/akvf
DATA=${AKVF_DATA_DIR:-../shared/meshes}
[ -x "$AKVF" ] || { echo "build first: bash scripts/build.sh" >&2; exit 1; }
[ -d "$DATA/tri" ] || { echo "meshes not found in $DATA (set AKVF_DATA_DIR)" >&2; exit 1; }
