#!/bin/sh
# Download the distributions of every pin of $1 for CPython 3.11, 3.12 and 3.13 on Linux x86_64 into $2/<version>
# (wheels; the source distribution of a pin that has no wheel for a version), for tools/hash_lock.py.
# Run by `make lock`.
set -eu
lock=$1; out=$2; py=${PYTHON:-python3}
plat="--implementation cp --platform manylinux_2_28_x86_64 --platform manylinux_2_27_x86_64 --platform manylinux_2_17_x86_64 --platform manylinux2014_x86_64"
for v in 3.11 3.12 3.13; do
  pv="$v.99"  # the newest patch release: some pins need e.g. >= 3.11.5 (Requires-Python)
  mkdir -p "$out/$v"
  sed 's/ --hash.*//' "$lock" > "$out/$v.pins"
  # all wheels in one pip call; a pin without a wheel for this version is named by pip, gets its sdist, and leaves the list
  while ! $py -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: --python-version "$pv" \
        $plat -d "$out/$v" -r "$out/$v.pins" 2> "$out/$v.err"; do
    pin=$(sed -n 's/.*No matching distribution found for \([^ ]*\).*/\1/p' "$out/$v.err" | head -1)
    [ -n "$pin" ] || { cat "$out/$v.err" >&2; exit 1; }
    echo "no wheel of $pin for CPython $v: locking its source distribution" >&2
    BEZIER_NO_EXTENSION=True $py -m pip download --quiet --disable-pip-version-check --no-deps --no-binary="${pin%%==*}" \
      -d "$out/$v" "$pin"
    grep -v "^$pin\$" "$out/$v.pins" > "$out/$v.pins.new" && mv "$out/$v.pins.new" "$out/$v.pins"
  done
  rm -f "$out/$v.pins" "$out/$v.err"
done
