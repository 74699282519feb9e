#!/usr/bin/env python3
"""How many content words of everyday English the ASL lexicon signs rather than fingerspells.

Runs `gestura gloss --json` once over every sentence of data/eval/everyday-sentences.txt and, for
each word the translator saw, classifies it:
  * function word (data/eval/function-words.txt): not counted; listed if it is fingerspelled;
  * spelled by convention: a capitalised name or a month, which ASL fingerspells anyway;
  * content word: signed (a sign or a number covers it) or fingerspelled / dropped (a miss).
Prints the coverage per domain and overall, and every missed word with its count.

    tools/coverage.py [--gestura build/bin/gestura] [--sentences FILE] [--min PERCENT] [--quiet]

Exit status 1 when the overall coverage is below --min (default 0).
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_sentences(path):
    """(domain, sentence) pairs; '## name' opens a domain, other '#' lines are comments."""
    domain = "all"
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line.startswith("##"):
                domain = line[2:].strip()
            elif line and not line.startswith("#"):
                out.append((domain, line))
    return out


def read_function_words(path):
    words = set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                words.update(line.split())
    return words


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gestura", default=os.path.join(ROOT, "build", "bin", "gestura"))
    ap.add_argument("--sentences", default=os.path.join(ROOT, "data", "eval", "everyday-sentences.txt"))
    ap.add_argument("--function-words", default=os.path.join(ROOT, "data", "eval", "function-words.txt"))
    ap.add_argument("--min", type=float, default=0.0, help="fail below this overall percentage")
    ap.add_argument("--quiet", action="store_true", help="only the summary line")
    args = ap.parse_args()

    sentences = read_sentences(args.sentences)
    function_words = read_function_words(args.function_words)
    # One run over all sentences (each ends with . ? or !), so the lexicon loads once.
    text = ""
    starts = []
    for _, s in sentences:
        if text:
            text += "\n"
        starts.append(len(text))
        text += s if s[-1] in ".?!" else s + "."
    run = subprocess.run([args.gestura, "gloss", "--json", text], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"gestura gloss failed: {run.stderr.strip()}")
    t = json.loads(run.stdout)

    def sentence_of(offset):
        lo, hi = 0, len(starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if starts[mid] <= offset:
                lo = mid
            else:
                hi = mid - 1
        return lo

    # Spans a sign or number covers (a fixed phrase's sign covers all of its words).
    covered = [(g["begin"], g["end"]) for g in t["glosses"] if g["kind"] in ("sign", "number")]

    per_domain = collections.OrderedDict()
    missed = collections.Counter()
    function_spelled = collections.Counter()
    conventional = collections.Counter()
    missed_in = collections.defaultdict(list)
    for n in t["notes"]:
        word = n["word"].lower().replace("\u2019", "'")
        if not re.search(r"[a-z]", word):
            continue  # numbers in digits, symbols
        domain = sentences[sentence_of(n["begin"])][0]
        d = per_domain.setdefault(domain, [0, 0])
        reason = n["reason"]
        spelled = " fingerspelled: " in reason or "(fingerspelled)" in reason or ", fingerspelled" in reason
        signed = not spelled and any(b <= n["begin"] and n["end"] <= e for b, e in covered)
        # An auxiliary the parse dropped ("have" of "have been waiting") is a function word here.
        if word in function_words or " dropped: auxiliary" in reason:
            if spelled:
                function_spelled[word] += 1
            continue
        if spelled and ("name (capitalized)" in reason or "month" in reason):
            conventional[n["word"]] += 1
            continue
        d[1] += 1
        if signed:
            d[0] += 1
        else:
            missed[word] += 1
            missed_in[word].append(sentences[sentence_of(n["begin"])][1])

    total = sum(v[1] for v in per_domain.values())
    signed_total = sum(v[0] for v in per_domain.values())
    pct = 100.0 * signed_total / total if total else 0.0
    if not args.quiet:
        print(f"{len(sentences)} sentences, {total} content words\n")
        print(f"{'domain':<28} {'signed':>7} {'words':>6} {'coverage':>9}")
        for domain, (s, w) in per_domain.items():
            print(f"{domain:<28} {s:>7} {w:>6} {100.0 * s / w:>8.1f}%")
        print()
        if missed:
            print(f"content words not signed ({sum(missed.values())} tokens, {len(missed)} words):")
            for word, count in sorted(missed.items(), key=lambda kv: (-kv[1], kv[0])):
                print(f"  {word:<16} {count:>3}  e.g. {missed_in[word][0]}")
            print()
        if function_spelled:
            print("function words fingerspelled (faults): " +
                  ", ".join(f"{w} ({c})" for w, c in sorted(function_spelled.items())))
        if conventional:
            print("fingerspelled by convention (names, months; not counted): " +
                  ", ".join(f"{w} ({c})" for w, c in sorted(conventional.items())))
        print()
    name = os.path.relpath(args.sentences, ROOT)
    print(f"coverage of {name}: {signed_total} of {total} content words signed = {pct:.1f}%")
    return 1 if pct < args.min else 0


if __name__ == "__main__":
    sys.exit(main())
