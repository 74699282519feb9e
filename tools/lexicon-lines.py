#!/usr/bin/env python3
"""Write lexicon lines from a compact form, and keep their HamNoSys Unicode equal to their names.

Compact form, one sign per line ('#' lines and blank lines are skipped):

    GLOSS | category | keyword, keyword, ... | symbol names | description

The symbol names are HamNoSys names, comma-separated; the "ham" prefix may be left out
(`flathand,extfingeru,palmd,chest`). The Unicode comes from the code points in
src/gestura/sign/hamnosys_symbol.cpp.

    tools/lexicon-lines.py compact FILE...           print the signs as JSON lines (lang ase, source gestura)
    tools/lexicon-lines.py merge LEXICON FILE...     add them to LEXICON, each at the end of its category's
                                                     block (new categories at the end); refuses a gloss or
                                                     keyword the lexicon already has
    tools/lexicon-lines.py fill LEXICON              rewrite every line's `hamnosys` from its `names`
    tools/lexicon-lines.py table LEXICON             print the Markdown table of glosses by category
                                                     (docs/asl-lexicon.md, "Signs")
"""
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SYMBOLS = os.path.join(ROOT, "src", "gestura", "sign", "hamnosys_symbol.cpp")
FIELDS = ("gloss", "lang", "category", "hamnosys", "names", "keywords", "description", "source", "licence")


def code_points():
    table = {}
    with open(SYMBOLS, encoding="utf-8") as f:
        for name, cp in re.findall(r'"(ham[a-z0-9]+)",\s*0x([0-9A-Fa-f]+)', f.read()):
            table[name] = chr(int(cp, 16))
    return table


CODES = code_points()


def full_names(names, where):
    out = []
    for raw in re.split(r"[,\s]+", names.strip()):
        if not raw:
            continue
        name = raw if raw.startswith("ham") else "ham" + raw
        if name not in CODES:
            raise SystemExit(f"{where}: unknown HamNoSys symbol '{raw}'")
        out.append(name)
    return out


def unicode_of(names):
    return "".join(CODES[n] for n in names)


def parse_compact(path):
    entries = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            where = f"{path}:{number}"
            parts = [p.strip() for p in line.split("|")]
            if len(parts) != 5:
                raise SystemExit(f"{where}: expected 5 fields separated by '|', found {len(parts)}")
            gloss, category, keywords, names, description = parts
            symbols = full_names(names, where)
            entries.append({
                "gloss": gloss,
                "lang": "ase",
                "category": category,
                "hamnosys": unicode_of(symbols),
                "names": ",".join(symbols),
                "keywords": [k.strip() for k in keywords.split(",") if k.strip()],
                "description": description,
                "source": "gestura",
                "licence": "CC0-1.0",
            })
    return entries


def dump(entry):
    return json.dumps({k: entry[k] for k in FIELDS if k in entry}, ensure_ascii=False)


def read_lexicon(path):
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def write_lexicon(path, entries):
    with open(path, "w", encoding="utf-8") as f:
        for e in entries:
            f.write(dump(e) + "\n")


def merge(path, new):
    old = read_lexicon(path)
    glosses = {e["gloss"] for e in old}
    keywords = {k: e["gloss"] for e in old for k in e["keywords"]}
    problems = []
    for e in new:
        if e["gloss"] in glosses:
            problems.append(f"gloss {e['gloss']} is already in the lexicon")
        glosses.add(e["gloss"])
        for k in e["keywords"]:
            if k in keywords:
                problems.append(f"keyword '{k}' of {e['gloss']} already belongs to {keywords[k]}")
            keywords[k] = e["gloss"]
    if problems:
        raise SystemExit("\n".join(problems))
    order = []
    blocks = {}
    for e in old + new:
        if e["category"] not in blocks:
            order.append(e["category"])
            blocks[e["category"]] = []
        blocks[e["category"]].append(e)
    write_lexicon(path, [e for c in order for e in blocks[c]])
    print(f"{path}: {len(new)} signs added, {len(old) + len(new)} in all")


CATEGORY_NAMES = {
    "pronoun": "Pronouns and pointing", "greeting": "Greetings, politeness, yes/no/not",
    "question": "Wh-words", "function": "Function signs, adverbs, prepositions, quantifiers, connectives",
    "verb": "Verbs", "noun": "Nouns (people, things, abstract)", "adjective": "Adjectives", "time": "Time",
    "day": "Days of the week", "colour": "Colours", "number": "Numbers", "home": "Home and household",
    "food": "Food and drink", "body": "Body", "health": "Health", "clothing": "Clothing",
    "travel": "Travel and transport", "place": "Places", "work": "Work", "school": "School",
    "shopping": "Shopping, money and sport", "nature": "Weather and nature", "animal": "Animals",
    "people": "People and society", "deaf": "Deaf life",
}


def table(path):
    entries = read_lexicon(path)
    order, blocks = [], {}
    for e in entries:
        if e["category"] not in blocks:
            order.append(e["category"])
            blocks[e["category"]] = []
        blocks[e["category"]].append(e["gloss"])
    known = [c for c in CATEGORY_NAMES if c in blocks]
    order = known + [c for c in order if c not in CATEGORY_NAMES]
    print("| category | count | glosses |")
    print("|---|---|---|")
    for c in order:
        print(f"| {CATEGORY_NAMES.get(c, c)} (`{c}`) | {len(blocks[c])} | {', '.join(blocks[c])} |")
    print(f"| **total** | **{len(entries)}** | |")


def main(argv):
    if len(argv) < 2 or argv[0] not in ("compact", "merge", "fill", "table"):
        raise SystemExit(__doc__)
    if argv[0] == "compact":
        for path in argv[1:]:
            for e in parse_compact(path):
                print(dump(e))
    elif argv[0] == "merge":
        if len(argv) < 3:
            raise SystemExit(__doc__)
        merge(argv[1], [e for p in argv[2:] for e in parse_compact(p)])
    elif argv[0] == "table":
        table(argv[1])
    else:
        entries = read_lexicon(argv[1])
        for e in entries:
            e["hamnosys"] = unicode_of(full_names(e["names"], e["gloss"]))
        write_lexicon(argv[1], entries)


if __name__ == "__main__":
    main(sys.argv[1:])
