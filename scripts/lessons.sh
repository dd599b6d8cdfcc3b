#!/bin/sh
# Regenerates every picture of docs/lessons/: each lesson's script, scripts/lessons/NAME.sh,
# renders its small scene with the technique's intermediate buffers (render --debug-buffers)
# into docs/lessons/images/NAME/ and prints the figures the page quotes. Seconds to a few
# minutes a lesson on 2 cores; 03 about four (eight exact soft references) and 11 about
# twenty (each scored frame renders the exact environment integral). Crops and contrast
# stretches use ImageMagick, plots rsvg-convert (scripts/setup.sh installs both).
# usage: scripts/lessons.sh [NAME ...]   (default: every lesson, in order; NAME as 01-planar)
# The program is build/app/shadowlab unless SHADOWLAB names another.
set -eu
cd "$(dirname "$0")/.."
app=${SHADOWLAB:-build/app/shadowlab}
export app
if [ $# -eq 0 ]; then
  set -- $(ls scripts/lessons | sed -n 's/^\([0-9].*\)\.sh$/\1/p')   # not common.sh
fi
for lesson in "$@"; do
  script=scripts/lessons/$lesson.sh
  [ -f "$script" ] || { echo "lessons.sh: no lesson '$lesson' (see scripts/lessons/)" >&2; exit 1; }
  images=docs/lessons/images/$lesson
  rm -rf "$images"   # a picture the script no longer makes must not stay behind
  mkdir -p "$images" out/lessons/$lesson
  echo "== $lesson"
  images=$images scratch=out/lessons/$lesson sh "$script"
done
