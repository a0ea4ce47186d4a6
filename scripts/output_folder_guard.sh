# Sourced by the scripts that replace files and folders in an output folder of the user's
# choosing: they replace only what an earlier run of the same script made there.
#   refuse_unless_made_here OUT STAMP NAME...
# When one of the NAMEs exists in OUT and OUT holds no STAMP (written by an earlier run), exits 2
# naming it and touches nothing; otherwise writes STAMP, so that the next run may replace them.
refuse_unless_made_here() {
  local out="$1" stamp="$2" name
  shift 2
  if [ ! -e "$out/$stamp" ]; then
    for name in "$@"; do
      if [ -e "$out/$name" ] || [ -L "$out/$name" ]; then
        echo "$(basename "$0"): '$out/$name' exists and this script did not make it" \
          "('$out/$stamp' is missing): it would be replaced; move it, or choose another folder" >&2
        exit 2
      fi
    done
  fi
  : >"$out/$stamp"
}
