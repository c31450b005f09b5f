#!/bin/sh
# Download the distributions of every pin of $1 for CPython 3.11, 3.12 and 3.13 on Linux x86_64 into $2/<version>
# (wheels; the sdist of a pin without a wheel for a version), for tools/hash_lock.py.  Run by `make lock`.
set -eu
lock=$1; out=$2; py=${PYTHON:-python3}
sed 's/ --hash.*//' "$lock" > "$out.plain"
for v in 3.11 3.12 3.13; do
  mkdir -p "$out/$v"
  while read -r pin; do
    [ -n "$pin" ] || continue
    $py -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: --python-version "$v" \
      --implementation cp --platform manylinux_2_28_x86_64 --platform manylinux_2_27_x86_64 \
      --platform manylinux_2_17_x86_64 --platform manylinux2014_x86_64 -d "$out/$v" "$pin" 2>/dev/null || {
      echo "no wheel of $pin for CPython $v: locking its source distribution" >&2
      BEZIER_NO_EXTENSION=True $py -m pip download --quiet --disable-pip-version-check --no-deps --no-binary="${pin%%==*}" -d "$out/$v" "$pin"; }
  done < "$out.plain"
done
rm -f "$out.plain"
