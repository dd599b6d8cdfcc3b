# What the lessons' scripts share; each sources it after `set -eu` (scripts/lessons.sh runs
# them from the repository's root with $app, $images and $scratch set).

# The figures the pages quote, as Markdown tables from render --json files.
figures="python3 scripts/lessons/lesson_figures.py"
# ImageMagick, without the time stamps it would write into each PNG (same bytes every run).
convert="convert -define png:exclude-chunks=date,time"

# need_convert: stops with a one-line error unless ImageMagick is installed.
need_convert() {
  command -v convert > /dev/null && return
  echo "$0: needs ImageMagick's convert (apt-get install imagemagick)" >&2
  exit 1
}

# render NAME SCENE TECHNIQUE [ARGS]: the image, its error map against the technique's exact
# reference and the figures, as $scratch/NAME.png, NAME-error.png and NAME.json ($size, set
# by the lesson, gives the image's size and threads).
render() {
  name=$1 scene=$2 technique=$3
  shift 3
  nice -n 10 "$app" render "$scene" --technique "$technique" $size "$@" -o "$scratch/$name.png" \
    --error-map "$scratch/$name-error.png" --json "$scratch/$name.json" > "$scratch/$name.log"
}
# render_shown NAME SCENE TECHNIQUE [ARGS]: render, then show the image and its error map.
render_shown() {
  render "$@"
  show "$1" "$1-error"
}
# show FILE ...: copies the pictures the page shows from $scratch into the lesson's images.
show() { for file in "$@"; do cp "$scratch/$file.png" "$images/$file.png"; done; }
# keep DEBUG_NAME SHOWN_NAME: copies one debug buffer's PNG into the lesson's images.
keep() { cp "$scratch/debug/$1.png" "$images/$2.png"; }
