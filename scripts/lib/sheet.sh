# tl_sheet OUT PRESET LABEL TIMELINE:TIME...: renders each shot at
# 1280x720 with PRESET and tiles them two across at half size, in the
# order given (left to right, top to bottom), into the PNG OUT; LABEL
# prefixes the progress lines. The contact sheets (scripts/contact-sheet.sh,
# scripts/boat-sheet.sh) are shot lists for it. Needs build/tideline and
# the ffmpeg program; an odd count leaves the last tile black.
tl_sheet() {
  local out=$1 preset=$2 label=$3
  shift 3
  local shots=("$@") scratch inputs=() filter="" rows="" i timeline time
  ((${#shots[@]} % 2)) && shots+=("")
  scratch=$(mktemp -d)
  for i in "${!shots[@]}"; do
    if [ -z "${shots[$i]}" ]; then
      ffmpeg -loglevel error -f lavfi -i color=black:s=1280x720 -frames:v 1 "$scratch/$i.png"
    else
      timeline=${shots[$i]%:*} time=${shots[$i]##*:}
      echo "$label: $timeline at $time s ($((i + 1)) of ${#shots[@]})"
      if ! build/tideline still "$timeline" --time "$time" --size 1280x720 --quality "$preset" \
        -o "$scratch/$i.png"; then
        rm -rf "$scratch"
        return 1
      fi
    fi
    inputs+=(-i "$scratch/$i.png")
  done
  for ((i = 0; i < ${#shots[@]}; i += 2)); do
    filter+="[$i]scale=640:360[a$i];[$((i + 1))]scale=640:360[b$i];[a$i][b$i]hstack[r$i];"
    rows+="[r$i]"
  done
  filter+="${rows}vstack=inputs=$((${#shots[@]} / 2))"
  ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "$filter" "$scratch/sheet.png" &&
    mv "$scratch/sheet.png" "$out"
  local rc=$?
  rm -rf "$scratch"
  ((rc == 0)) && echo "$label: $out"
  return $rc
}

# tl_grid OUT COLUMNS DIR NAME...: tiles DIR/NAME.png, each labelled with
# its NAME at the top left, COLUMNS across in the order given, into the PNG
# OUT (the count a multiple of COLUMNS). For the sheets whose tiles are
# layers of one frame (scripts/passes-sheet.sh, scripts/layers-sheet.sh).
tl_grid() {
  local out=$1 columns=$2 dir=$3
  shift 3
  local names=("$@") inputs=() filter="" rows="" i n
  for n in "${names[@]}"; do
    ffmpeg -loglevel error -y -i "$dir/$n.png" -vf \
      "drawtext=text='$n':x=8:y=8:fontsize=22:fontcolor=white:box=1:boxcolor=black@0.6" \
      "$dir/label_$n.png" 2>/dev/null || cp "$dir/$n.png" "$dir/label_$n.png"
    inputs+=(-i "$dir/label_$n.png")
  done
  for ((i = 0; i < ${#names[@]}; i += columns)); do
    local row=""
    for ((n = i; n < i + columns; n++)); do row+="[$n]"; done
    filter+="${row}hstack=inputs=$columns[r$i];"
    rows+="[r$i]"
  done
  filter+="${rows}vstack=inputs=$((${#names[@]} / columns))"
  ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "$filter" "$out"
}
