#!/usr/bin/env python3
"""How many of the most frequent English lemmas (WordNet sense-frequency counts) get an ASL sign.

Sums the tag counts of /usr/share/wordnet/cntlist.rev (Debian wordnet-base) per lemma, leaves out the
words of data/eval/function-words.txt, and translates each of the N most frequent lemmas on its own
with `gestura gloss`; a lemma counts as signed when a sign or number covers it.

    tools/wordnet-coverage.py [--top 500 1000 1500] [--list-missed 1000]
    GESTURA_BUILTIN_LEXICON=old.jsonl tools/wordnet-coverage.py     # another lexicon
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--gestura", default=os.path.join(ROOT, "build", "bin", "gestura"))
    ap.add_argument("--cntlist", default="/usr/share/wordnet/cntlist.rev")
    ap.add_argument("--function-words", default=os.path.join(ROOT, "data", "eval", "function-words.txt"))
    ap.add_argument("--top", type=int, nargs="+", default=[500, 1000, 1500])
    ap.add_argument("--list-missed", type=int, default=0, metavar="N",
                    help="list the lemmas among the N most frequent that are not signed")
    args = ap.parse_args()

    if not os.path.exists(args.cntlist):
        sys.exit(f"{args.cntlist} not found (apt-get install wordnet-base)")
    function_words = set()
    for line in open(args.function_words, encoding="utf-8"):
        line = line.split("#", 1)[0].strip().lower()
        if line:
            function_words.update(line.split())

    counts = collections.Counter()
    for line in open(args.cntlist, encoding="utf-8"):
        parts = line.split()
        if len(parts) != 3:
            continue
        lemma = parts[0].split("%", 1)[0].replace("_", " ")
        if re.fullmatch(r"[a-z][a-z' -]*", lemma) and lemma not in function_words:
            counts[lemma] += int(parts[2])
    ranked = [w for w, _ in counts.most_common(max(args.top + [args.list_missed]))]

    text, starts = "", []
    for w in ranked:
        if text:
            text += "\n"
        starts.append(len(text))
        text += w + "."
    run = subprocess.run([args.gestura, "gloss", "--json", text], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"gestura gloss failed: {run.stderr.strip()}")
    glosses = json.loads(run.stdout)["glosses"]
    covered = [(g["begin"], g["end"]) for g in glosses if g["kind"] in ("sign", "number")]
    spelled = [(g["begin"], g["end"]) for g in glosses if g["kind"] not in ("sign", "number")]

    def signed(i):
        b, e = starts[i], starts[i] + len(ranked[i])
        inside = lambda spans: any(sb < e and b < se for sb, se in spans)
        return inside(covered) and not inside(spelled)

    ok = [signed(i) for i in range(len(ranked))]
    for n in args.top:
        k = sum(ok[:n])
        print(f"top {n} WordNet lemmas (function words left out): {k} signed = {100.0 * k / n:.1f}%")
    if args.list_missed:
        missed = [ranked[i] for i in range(min(args.list_missed, len(ranked))) if not ok[i]]
        print(f"\nnot signed among the top {args.list_missed} ({len(missed)}):")
        print(", ".join(missed))


if __name__ == "__main__":
    main()
