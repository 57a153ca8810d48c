#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the hostile evaluation files of this folder from a valid evaluation folder.

    make_corpus.py BASE_FOLDER

BASE_FOLDER: the evaluation that test/cli/bad_evaluation.sh makes first (its `base` folder). Each
file here replaces one file of that folder (EXPECTED.txt says which, and what the tool must say).
"""
import json
import os
import sys

base = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))


def text(name):
    with open(os.path.join(base, name), encoding="utf-8") as f:
        return f.read()


def load(name):
    return json.loads(text(name))


def write(name, content):
    with open(os.path.join(here, name), "w", encoding="utf-8", newline="") as f:
        f.write(content if isinstance(content, str) else json.dumps(content, indent=2) + "\n")


MODEL = "models/sphere.xyz.json"


def model(name, change):
    m = load(MODEL)
    change(m)
    write(name, m)


def summary(name, change):
    s = load("summary.json")
    change(s)
    write(name, s)


def failures(name, change):
    f = load("failures.json")
    change(f)
    write(name, f)


def setitem(d, path, value):
    for key in path[:-1]:
        d = d[key]
    d[path[-1]] = value


model_text = text(MODEL)
write("model_truncated.json", model_text[: len(model_text) // 3])
write("model_nan_token.json", model_text.replace('"sum": ', '"sum": NaN, "x": ', 1))
write("model_number_overflow.json", model_text.replace('"sum": ', '"sum": 1e400, "x": ', 1))
write("model_empty.json", "")
write("model_binary_garbage.json", "".join(chr(c) for c in range(1, 127)) * 3)
write("model_top_level_array.json", "[1, 2, 3]\n")
write("model_deep_nesting.json", '{"model": ' + "[" * 17 + "]" * 17 + "}\n")
model("model_k_max_4e9.json", lambda m: setitem(m, ["settings", "k_max"], 4000000000))
model("model_k_max_twenty.json", lambda m: setitem(m, ["settings", "k_max"], "twenty"))
model("model_k_min_zero.json", lambda m: setitem(m, ["settings", "k_min"], 0))
model("model_grid_value_7_5.json", lambda m: setitem(m, ["settings", "a_grid", 2], 7.5))
model("model_grid_unsorted.json", lambda m: m["settings"]["b_grid"].reverse())
model("model_grid_empty.json", lambda m: setitem(m, ["settings", "b_grid"], []))
model("model_missing_key.json", lambda m: m["settings"].pop("fixed_k"))
model("model_negative_count.json", lambda m: setitem(m, ["statistics", "points"], -5))
model("model_count_as_float.json", lambda m: setitem(m, ["statistics", "equal", "count"], 60.5))
model("model_name_is_a_number.json", lambda m: setitem(m, ["model"], 5))
model("model_name_of_another_model.json", lambda m: setitem(m, ["model"], "other.xyz"))
model("model_unknown_key.json", lambda m: setitem(m, ["extra"], 1))
model("model_failures_not_the_statistics.json", lambda m: setitem(m, ["failures"], 3))
model("model_labels_exceed_count.json", lambda m: setitem(m, ["statistics", "equal", "labels", "linear"], 1000))
model("model_mean_edited.json", lambda m: setitem(m, ["statistics", "optimal", "mean"], 0.25))
model("model_counts_not_the_points.json",
      lambda m: setitem(m, ["statistics", "cut_off", "count"], m["statistics"]["cut_off"]["count"] + 1))
model("model_k_histogram_short.json", lambda m: m["statistics"]["equal"]["k_histogram"].pop())
model("model_pair_histogram_beyond_table3.json", lambda m: setitem(m, ["statistics", "pair_k_histogram", 0], 1000))
model("model_table3_a_and_b_differ.json",
      lambda m: setitem(m, ["statistics", "table3", "a_zero"], m["statistics"]["table3"]["a_zero"] + 1))
model("model_k_mean_edited.json", lambda m: setitem(m, ["statistics", "k_mean"], 3.0))
model("model_estimated_keys_with_file_normals.json", lambda m: setitem(m, ["normal_method"], "pca"))
model("model_min_above_max.json", lambda m: setitem(m, ["statistics", "equal", "min"], 2.0))
model("model_settings_is_a_string.json", lambda m: setitem(m, ["settings"], "default"))
model("model_zero_normals_beyond_points.json", lambda m: setitem(m, ["zero_normals"], 1000))

summary_text = text("summary.json")
write("summary_truncated.json", summary_text[:144])
write("summary_nan_token.json", summary_text.replace('"points": ', '"points": NaN, "x": ', 1))
write("summary_top_level_array.json", "[]\n")
summary("summary_negative_count.json", lambda s: setitem(s, ["points"], -100))
summary("summary_points_edited.json", lambda s: setitem(s, ["points"], s["points"] + 1))
summary("summary_k_mean_edited.json", lambda s: setitem(s, ["statistics", "k_mean"], 3.0))
summary("summary_extra_model.json", lambda s: s["per_model"].append(dict(s["per_model"][0], model="ghost.xyz")))
summary("summary_repository_is_a_number.json", lambda s: setitem(s, ["repository"], 7))
summary("summary_k_max_4e9.json", lambda s: setitem(s, ["settings", "k_max"], 4000000000))

failures("failures_not_an_array.json", lambda f: setitem(f, ["failures"], {}))
failures("failures_missing_message.json", lambda f: f["failures"][0].pop("message"))
failures("failures_lists_an_evaluated_model.json",
         lambda f: f["failures"].append({"model": "sphere.xyz", "message": "forged"}))
failures("failures_unknown_key.json", lambda f: setitem(f, ["skipped"], []))
failures("failures_too_small_not_small.json", lambda f: setitem(f, ["too_small", 0, "points"], 30))
