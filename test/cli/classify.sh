#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# sigmoid-neighborhoods classify on CGAL's labeled b9 scan: train, predict, evaluate, and the refusals
# (no labels, a damaged or forged model, other labels); every refusal exits 2 and writes nothing.
# usage: classify.sh TOOL b9_training.ply
set -eu
tool=$1
b9=$2
dir=classify-test
rm -rf "$dir" && mkdir -p "$dir"
labels=ground=0,vegetation=1,roof=2
fail() { echo "FAILED: $*"; exit 1; }
expect_refusal() { # expected message piece, then the command
  piece=$1; shift
  set +e; "$@" > "$dir/out.txt" 2> "$dir/err.txt"; code=$?; set -e
  [ "$code" -eq 2 ] || fail "exit $code, not 2: $* ($(cat "$dir/err.txt"))"
  grep -q -- "$piece" "$dir/err.txt" || fail "no '$piece' in: $(cat "$dir/err.txt")"
}

"$tool" classify train "$b9" -o "$dir/model.bin" --labels $labels --features k20,optimal,height --trees 10 \
  2> "$dir/train.txt" || fail "train: $(cat "$dir/train.txt")"
grep -q "model.bin: 34 features, 3 classes, 22300 points" "$dir/train.txt" || fail "train summary: $(cat "$dir/train.txt")"
head -1 "$dir/model.bin" | grep -q "sigmoid-neighborhoods classifier 1" || fail "model magic"

# the trees trained on 1 and 2 threads (the package's loop) on CGAL's features and ours: the same
# forest; at most 500 points a class (two classes of b9 capped, the third has 314)
for threads in 1 2; do
  "$tool" classify train "$b9" -o "$dir/capped$threads.bin" --labels $labels --features cgal,k20 --trees 4 \
    --max-per-class 500 --threads $threads 2> "$dir/capped.txt" || fail "train capped: $(cat "$dir/capped.txt")"
done
grep -q "22300 points from 1 file(s) (1314 trained on)" "$dir/capped.txt" || fail "capped summary: $(cat "$dir/capped.txt")"
sed -n 2p "$dir/capped1.bin" | grep -q '"max_per_class":500' || fail "the cap is not in the model"
# the same trees: the same predictions, byte for byte (the model files are compared without their forests:
# CGAL's writer stores the threshold of a split it could not make uninitialised, which may differ)
head -2 "$dir/capped1.bin" > "$dir/capped1.head"; head -2 "$dir/capped2.bin" > "$dir/capped2.head"
cmp "$dir/capped1.head" "$dir/capped2.head" || fail "the models of 1 and 2 threads differ"
for threads in 1 2; do
  "$tool" classify predict "$dir/capped$threads.bin" "$b9" -o "$dir/capped$threads.ply" --threads $threads \
    2> "$dir/capped_predict.txt" || fail "predict capped: $(cat "$dir/capped_predict.txt")"
done
cmp "$dir/capped1.ply" "$dir/capped2.ply" || fail "the forests of 1 and 2 threads predict differently"

# --choose-scales: the first scale in metres chosen on the training file among the ladder, stored with
# its scores; the voxel and the pyramid's cell are that scale; refused beside a given voxel
"$tool" classify train "$b9" -o "$dir/chosen.bin" --labels $labels --features cgal-metric,pyramid --trees 2 \
  --choose-scales 2> "$dir/chosen.txt" || fail "train --choose-scales: $(cat "$dir/chosen.txt")"
grep -q "first scale in metres chosen: " "$dir/chosen.txt" || fail "choice summary: $(cat "$dir/chosen.txt")"
chosen=$(sed -n 2p "$dir/chosen.bin" | grep -o '"chosen":[0-9.]*' | cut -d: -f2)
case "$chosen" in 0.0625|0.125|0.25|0.5|1.0) ;; *) fail "chosen scale '$chosen' is not on the ladder" ;; esac
sed -n 2p "$dir/chosen.bin" | grep -q "\"cgal_voxel\":$chosen," || fail "the voxel is not the chosen scale"
sed -n 2p "$dir/chosen.bin" | grep -q "\"cell\":$chosen," || fail "the pyramid's cell is not the chosen scale"
sed -n 2p "$dir/chosen.bin" | grep -q '"ladder":\[0.0625,0.125,0.25,0.5,1.0\]' || fail "the ladder is not in the model"
"$tool" classify predict "$dir/chosen.bin" "$b9" -o "$dir/chosen.ply" 2> "$dir/chosen_predict.txt" ||
  fail "predict with a chosen scale: $(cat "$dir/chosen_predict.txt")"
expect_refusal "--choose-scales chooses --cgal-voxel and --pyramid-cell" "$tool" classify train "$b9" \
  -o "$dir/none.bin" --labels $labels --features cgal-metric --choose-scales --cgal-voxel 1
expect_refusal "--choose-scales: no group of --features has scales in metres" "$tool" classify train "$b9" \
  -o "$dir/none.bin" --labels $labels --features k20 --choose-scales

# The choice over several files with a group without scales in metres (computed once per file, at the
# points the folds' forests read): the same model on 1 and 2 threads but for the choice's seconds, and
# the chosen scale is the ladder's best worse-of-two score, ties to the coarser
for threads in 1 2; do
  "$tool" classify train "$b9" "$b9" -o "$dir/chosen_two$threads.bin" --labels $labels \
    --features cgal-metric,multiscale-sigmoid --scales 10,25 --trees 2 --threads $threads 2> "$dir/chosen_two.txt" ||
    fail "train two files, scales chosen: $(cat "$dir/chosen_two.txt")"
  sed 's/"seconds":[0-9.eE+-]*//' "$dir/chosen_two$threads.bin" > "$dir/chosen_two$threads.cmp"
done
cmp -s "$dir/chosen_two1.cmp" "$dir/chosen_two2.cmp" || fail "the choice differs on 1 and 2 threads"
sed -n 2p "$dir/chosen_two1.bin" | tr -d ' ' | grep -o '"\(ladder\|same_density\|thinned\)":\[[^]]*\|"chosen":[0-9.]*' |
  tr -d '"[' | awk -F: '{ n = split($2, v, ","); for(i = 1; i <= n; ++i) x[$1, i] = v[i]; size = n }
    END { best = -1; for(i = 1; i <= size; ++i) { s = x["same_density", i] + 0; t = x["thinned", i] + 0;
            w = s < t ? s : t; if(w < 0 || w > 1) exit 1; if(w >= best) { best = w; pick = x["ladder", i] + 0 } }
          if(size != 5 || pick != x["chosen", 1] + 0) exit 1 }' ||
  fail "the chosen scale is not the ladder's best: $(sed -n 2p "$dir/chosen_two1.bin" | grep -o '"scale_choice":{[^}]*}')"

# --sigmoid: the weights of multiscale-sigmoid, stored in the model (20deg and 50deg in radians);
# more than two angles or one out of [0, pi] is refused
"$tool" classify train "$b9" -o "$dir/sigmoid.bin" --labels $labels --features multiscale-sigmoid --trees 2 \
  --sigmoid 50deg,20deg 2> "$dir/sigmoid.txt" || fail "train --sigmoid: $(cat "$dir/sigmoid.txt")"
sed -n 2p "$dir/sigmoid.bin" | grep -q '"sigmoid":\[0\.34906585039886[0-9]*,0\.87266462599716[0-9]*\]' ||
  fail "the sigmoid is not in the model: $(sed -n 2p "$dir/sigmoid.bin" | head -c 600)"
expect_refusal "--sigmoid needs the two angles" "$tool" classify train "$b9" -o "$dir/bad_sigmoid.bin" \
  --labels $labels --features multiscale-sigmoid --sigmoid 10deg,20deg,30deg
expect_refusal "200deg is not in" "$tool" classify train "$b9" -o "$dir/bad_sigmoid.bin" --labels $labels \
  --features multiscale-sigmoid --sigmoid 200deg
[ ! -e "$dir/bad_sigmoid.bin" ] || fail "a refused --sigmoid wrote a model"

# CGAL's scales in metres (cgal-metric, --cgal-voxel, --cgal-scales) and the sigmoid weights on some levels of the
# pyramid only, stored in the model and applied by predict
"$tool" classify train "$b9" -o "$dir/metric.bin" --labels $labels --features cgal-metric,pyramid-sigmoid \
  --trees 2 --cgal-voxel 0.5 --cgal-scales 2 --pyramid-cell 1 --pyramid-levels 3 --pyramid-sigmoid-cells 2,1 \
  2> "$dir/metric.txt" || fail "train --cgal-voxel: $(cat "$dir/metric.txt")"
header=$(sed -n 2p "$dir/metric.bin")
for piece in '"cgal_scales":2' '"cgal_voxel":0.5' '"sigmoid_cells":\[2.0,1.0\]' '"linearity_sigmoid_pyr1"' \
             '"linearity_sigmoid_pyr2"' '"linearity_pyr4"' '"vertical_range_pyr4"'; do
  echo "$header" | grep -q "$piece" || fail "no $piece in the model: $(echo "$header" | head -c 600)"
done
! echo "$header" | grep -q '"linearity_sigmoid_pyr4"\|"linearity_pyr1"' || fail "a level with both weights or none"
# two scales of CGAL's features, not its five: two names per eigenvalue (scale 0 and 1)
[ "$(echo "$header" | grep -o '"eigenvalue[a-z_]*0_[0-9]*"' | sort -u | wc -l)" -eq 2 ] ||
  fail "not two scales of CGAL's eigenvalues: $(echo "$header" | grep -o '"eigenvalue[a-z_0-9]*"' | sort -u | tr '\n' ' ')"
"$tool" classify predict "$dir/metric.bin" "$b9" -o "$dir/metric.ply" 2> "$dir/metric_predict.txt" ||
  fail "predict with --cgal-voxel: $(cat "$dir/metric_predict.txt")"
{ head -1 "$dir/metric.bin"; sed -n 2p "$dir/metric.bin" | sed 's/"cgal_voxel":0.5/"cgal_voxel":0.0/'; tail -n +3 "$dir/metric.bin"; } \
  > "$dir/forged_voxel.bin"
expect_refusal "not a usable classifier model" "$tool" classify predict "$dir/forged_voxel.bin" "$b9" -o "$dir/none.ply"
# the voxel is read: another one, other features, another forest (the same seed and settings otherwise)
for voxel in 0.5 1; do
  "$tool" classify train "$b9" -o "$dir/voxel$voxel.bin" --labels $labels --features cgal-metric --cgal-scales 2 \
    --cgal-voxel $voxel --trees 2 2> "$dir/voxel.txt" || fail "train --cgal-voxel $voxel: $(cat "$dir/voxel.txt")"
done
tail -n +3 "$dir/voxel0.5.bin" > "$dir/forest0.5"; tail -n +3 "$dir/voxel1.bin" > "$dir/forest1"
! cmp -s "$dir/forest0.5" "$dir/forest1" || fail "the forests of two voxels are the same: the voxel is not read"
# by default the scales in metres are chosen wherever a group has them and none is given; given, not
# chosen; where the files cannot tell them apart (points on the diagonal of the checkerboard: one
# fold), 0.5 m, said on the summary line, and with --choose-scales a refusal
"$tool" classify train "$b9" -o "$dir/default_metric.bin" --labels $labels --features cgal-metric,pyramid \
  --trees 2 2> "$dir/default_metric.txt" || fail "train cgal-metric: $(cat "$dir/default_metric.txt")"
grep -q "first scale in metres chosen: " "$dir/default_metric.txt" || fail "no choice by default: $(cat "$dir/default_metric.txt")"
sed -n 2p "$dir/default_metric.bin" | grep -q '"scale_choice":' || fail "no choice in the default model"
! grep -q "first scale in metres" "$dir/voxel.txt" || fail "a given voxel was chosen again: $(cat "$dir/voxel.txt")"
! sed -n 2p "$dir/voxel1.bin" | grep -q '"scale_choice":' || fail "a choice in a model of a given voxel"
printf 'ply\nformat ascii 1.0\nelement vertex 60\nproperty float x\nproperty float y\nproperty float z\nproperty int label\nend_header\n' > "$dir/diagonal.ply"
i=0; while [ $i -lt 60 ]; do echo "$i $i $((i % 4)) $((i % 3))" >> "$dir/diagonal.ply"; i=$((i + 1)); done
"$tool" classify train "$dir/diagonal.ply" -o "$dir/diagonal.bin" --labels $labels --features cgal-metric --trees 2 \
  2> "$dir/diagonal.txt" || fail "train on one fold: $(cat "$dir/diagonal.txt")"
grep -q "first scale in metres not chosen (too few labeled points.*): 0.5 m" "$dir/diagonal.txt" ||
  fail "no fallback: $(cat "$dir/diagonal.txt")"
expect_refusal "too few labeled points to choose the scales in metres" "$tool" classify train "$dir/diagonal.ply" \
  -o "$dir/none.bin" --labels $labels --features cgal-metric --choose-scales

expect_refusal "not a cell size of the pyramid" "$tool" classify train "$b9" -o "$dir/bad_metric.bin" --labels $labels \
  --features pyramid-sigmoid --pyramid-cell 1 --pyramid-sigmoid-cells 3
expect_refusal "must be a positive voxel size" "$tool" classify train "$b9" -o "$dir/bad_metric.bin" --labels $labels \
  --features cgal-metric --cgal-voxel 0
expect_refusal "cgal, cgal-metric and cgal-grid share CGAL's features" "$tool" classify train "$b9" \
  -o "$dir/bad_metric.bin" --labels $labels --features cgal,cgal-metric
expect_refusal "cgal, cgal-metric and cgal-grid share CGAL's features" "$tool" classify train "$b9" \
  -o "$dir/bad_metric.bin" --labels $labels --features cgal-grid,cgal-metric

# cgal-grid: the grids' features of cgal-metric alone (no eigen analysis), at the model's voxel and scales
"$tool" classify train "$b9" -o "$dir/grid.bin" --labels $labels --features cgal-grid,k20 --cgal-voxel 1 \
  --cgal-scales 2 --trees 2 2> "$dir/grid.txt" || fail "train cgal-grid: $(cat "$dir/grid.txt")"
grep -q "grid.bin: 20 features" "$dir/grid.txt" || fail "cgal-grid: not 2 x 5 grid features and k20's: $(cat "$dir/grid.txt")"
header=$(sed -n 2p "$dir/grid.bin")
for piece in '"cgal_voxel":1.0' '"cgal_scales":2' '"elevation_1"' '"vertical_dispersion_0"' '"vertical_range_1"'; do
  echo "$header" | grep -q "$piece" || fail "no $piece in the cgal-grid model: $(echo "$header" | head -c 600)"
done
! echo "$header" | grep -q '"eigenvalue\|"distance_to_plane\|"verticality_[0-9]' || fail "cgal-grid has eigen features"
"$tool" classify predict "$dir/grid.bin" "$b9" -o "$dir/grid.ply" 2> "$dir/grid_predict.txt" ||
  fail "predict with cgal-grid: $(cat "$dir/grid_predict.txt")"

# --scales: the neighbor counts of multiscale(-sigmoid), sorted, stored and named in the model
"$tool" classify train "$b9" -o "$dir/scales.bin" --labels $labels --features multiscale-sigmoid --scales 30,12,30 \
  --trees 2 2> "$dir/scales.txt" || fail "train --scales: $(cat "$dir/scales.txt")"
header=$(sed -n 2p "$dir/scales.bin")
for piece in '"scales":\[12,30\]' '"linearity_sigmoid_k12"' '"normal_z_sigmoid_k30"'; do
  echo "$header" | grep -q "$piece" || fail "no $piece in the --scales model: $(echo "$header" | head -c 600)"
done
! echo "$header" | grep -q '"linearity_sigmoid_k10"' || fail "--scales kept the default scales"
for bad in 0 10,x 10,-5 10001; do
  expect_refusal "is not a neighbor count of 1 to 10000" "$tool" classify train "$b9" -o "$dir/bad_scales.bin" \
    --labels $labels --features multiscale --scales "$bad"
done
expect_refusal "must be 1 to 32" "$tool" classify train "$b9" -o "$dir/bad_metric.bin" --labels $labels \
  --features cgal --cgal-scales 0
[ ! -e "$dir/bad_metric.bin" ] || fail "a refused option wrote a model"

"$tool" classify predict "$dir/model.bin" "$b9" -o "$dir/predicted.ply" --graphcut 0.2 2> "$dir/predict.txt" \
  || fail "predict: $(cat "$dir/predict.txt")"
for property in "element vertex 22300" "property int scalar_label" "property float scalar_confidence_ground" \
                "property float scalar_confidence_roof" "property int scalar_truth" "property uchar red"; do
  head -c 2000 "$dir/predicted.ply" | grep -a -q "$property" || fail "no '$property' in the PLY header"
done

# CloudCompare (when installed: make test installs it) opens the prediction with its scalar fields
if command -v CloudCompare > /dev/null; then
  ( cd "$dir" && QT_QPA_PLATFORM=offscreen timeout 120 CloudCompare -SILENT -NO_TIMESTAMP -O predicted.ply \
      -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS FILE predicted_cc.asc ) > "$dir/cc.txt" 2>&1 || fail "CloudCompare: $(cat "$dir/cc.txt")"
  header=$(head -1 "$dir/predicted_cc.asc")
  for field in label confidence_ground confidence_roof truth; do
    echo "$header" | grep -q "$field" || fail "CloudCompare did not load the field $field: $header"
  done
  [ "$(grep -c . "$dir/predicted_cc.asc")" -eq 22301 ] || fail "CloudCompare did not read 22300 points"
fi

"$tool" classify evaluate "$dir/model.bin" "$b9" -o "$dir/evaluation" 2> "$dir/evaluate.txt" \
  || fail "evaluate: $(cat "$dir/evaluate.txt")"
for f in evaluation.md evaluation.csv evaluation.json; do [ -s "$dir/evaluation/$f" ] || fail "no $f"; done
# the training scan itself: nearly every point right
grep -q '"mean_iou": 0\.9' "$dir/evaluation/evaluation.json" || fail "mean IoU below 0.9: $(cat "$dir/evaluate.txt")"
grep -q "^| ground | " "$dir/evaluation/evaluation.md" || fail "no ground row in evaluation.md"

# the experiment: two sets, two orders, with and without graph-cut, its table and its figure
"$tool" classify experiment --train "$b9" --test "$b9" -o "$dir/experiment" --orders 2 --sets "P=k20;Q=k20,height" \
  --labels $labels --trees 5 2> "$dir/experiment.txt" || fail "experiment: $(cat "$dir/experiment.txt")"
[ "$(wc -l < "$dir/experiment/runs.csv")" -eq 9 ] || fail "runs.csv: not 8 runs"
grep -q "^| Q | k20 + height | yes | 19 | 0\.[0-9]* \[0\.[0-9]*, 0\.[0-9]*\] |" "$dir/experiment/experiment.md" \
  || fail "no row of set Q in experiment.md"
[ -s "$dir/experiment/figure_tile.png" ] || fail "no figure"
head -1 "$dir/experiment/figure_tile.csv" | grep -q "^x,y,z,truth,P,Q$" || fail "figure columns"
# the experiment reads the feature options as train does: a pyramid of two levels, 2 x (10 + 3) features,
# and with both pyramid groups, the heights once and the sigmoid weights on one level: 26 + 10
"$tool" classify experiment --train "$b9" --test "$b9" -o "$dir/experiment_pyramid" --orders 1 --cv-orders 0 \
  --sets "P=pyramid;PS=pyramid,pyramid-sigmoid" --labels $labels --trees 2 --pyramid-cell 2 --pyramid-levels 2 \
  --pyramid-sigmoid-cells 4 2> "$dir/experiment_pyramid.txt" ||
  fail "experiment --pyramid-levels: $(cat "$dir/experiment_pyramid.txt")"
grep -q "^| P | pyramid | no | 26 |" "$dir/experiment_pyramid/experiment.md" ||
  fail "the experiment's pyramid is not of two levels: $(grep '^| P' "$dir/experiment_pyramid/experiment.md")"
grep -q "^| PS | pyramid + pyramid-sigmoid | no | 36 |" "$dir/experiment_pyramid/experiment.md" ||
  fail "the experiment's two pyramid groups are not train's: $(grep '^| PS' "$dir/experiment_pyramid/experiment.md")"
# --choose-scales: each set with scales in metres at the scale train chooses for it (the same ladder's
# scores as train's model above), the other sets as they were; refused without such a set
"$tool" classify experiment --train "$b9" --test "$b9" -o "$dir/experiment_chosen" --orders 1 --cv-orders 0 \
  --sets "K=k20;MP=cgal-metric,pyramid" --labels $labels --trees 2 --graphcut 0 --choose-scales \
  2> "$dir/experiment_chosen.txt" || fail "experiment --choose-scales: $(cat "$dir/experiment_chosen.txt")"
shortest=$(echo "$chosen" | sed 's/\.0$//') # the report's numbers are the shortest that read back
grep -q "^| MP | cgal-metric + pyramid, first scale $shortest m (chosen) | no |" "$dir/experiment_chosen/experiment.md" ||
  fail "the experiment's set MP is not at train's scale $chosen: $(grep '^| MP' "$dir/experiment_chosen/experiment.md")"
grep -q "^| K | k20 | no |" "$dir/experiment_chosen/experiment.md" || fail "the set K changed with --choose-scales"
ladder_of() { grep -o '"\(same_density\|thinned\)":\[[^]]*\]' "$1"; }
tr -d ' \n' < "$dir/experiment_chosen/experiment.json" | ladder_of /dev/stdin | head -2 > "$dir/experiment_ladder.txt"
sed -n 2p "$dir/chosen.bin" | ladder_of /dev/stdin > "$dir/train_ladder.txt"
[ -s "$dir/train_ladder.txt" ] && cmp -s "$dir/experiment_ladder.txt" "$dir/train_ladder.txt" ||
  fail "the experiment's ladder is not train's: $(cat "$dir/experiment_ladder.txt") / $(cat "$dir/train_ladder.txt")"
tail -1 "$dir/experiment_chosen/experiment.csv" | grep -q ",$shortest$" || fail "no chosen scale in experiment.csv"
expect_refusal "--choose-scales: no set of --sets has a group with scales in metres" "$tool" classify experiment \
  --train "$b9" --test "$b9" -o "$dir/experiment_none" --sets "K=k20" --labels $labels --choose-scales
[ ! -e "$dir/experiment_none" ] || fail "a refused experiment made its folder"

# refusals, nothing written
printf 'ply\nformat ascii 1.0\nelement vertex 30\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$dir/unlabeled.ply"
i=0; while [ $i -lt 30 ]; do echo "$i $((i * i % 7)) $((i % 5))" >> "$dir/unlabeled.ply"; i=$((i + 1)); done
expect_refusal "has no labels" "$tool" classify train "$dir/unlabeled.ply" -o "$dir/none.bin" --labels $labels --features k20
[ ! -e "$dir/none.bin" ] || fail "a model was written for a file without labels"
expect_refusal "unknown group 'colour'" "$tool" classify train "$b9" -o "$dir/none.bin" --features k20,colour
expect_refusal "code 2 is in two classes" "$tool" classify train "$b9" -o "$dir/none.bin" --labels a=2,b=2
head -c 300 "$dir/model.bin" > "$dir/truncated.bin"
expect_refusal "not a usable classifier model" "$tool" classify predict "$dir/truncated.bin" "$b9" -o "$dir/none.ply"
echo "something else" > "$dir/other.bin"
expect_refusal "not a classifier model of sigmoid-neighborhoods" "$tool" classify predict "$dir/other.bin" "$b9" -o "$dir/none.ply"
{ echo "sigmoid-neighborhoods classifier 1"; printf '%*s' 20000 '' | tr ' ' '['; echo; } > "$dir/nested.bin"
expect_refusal "nest" "$tool" classify predict "$dir/nested.bin" "$b9" -o "$dir/none.ply"
{ head -1 "$dir/model.bin"; sed -n 2p "$dir/model.bin" | sed 's/"k_max":20/"k_max":"twenty"/'; } > "$dir/forged.bin"
expect_refusal "not a usable classifier model" "$tool" classify predict "$dir/forged.bin" "$b9" -o "$dir/none.ply"
expect_refusal "differ from the model's" "$tool" classify evaluate "$dir/model.bin" "$b9" -o "$dir/none" --labels ground=0,rest=1+2
[ ! -e "$dir/none.ply" ] && [ ! -e "$dir/none" ] || fail "a refused command wrote its output"
echo "classify-ok"
