#!/usr/bin/env python3
"""Turns the text output of collide_bench, collide_bench_manifold2, collide_bench_manifold3 or
collide_bench_scenes into CSV rows (stdout), so that runs can be kept in bench/results/<machine>/
and compared.

Usage: to_csv.py collide_bench|manifold2|manifold3|scenes RUN.txt > RUN.csv
(collide_bench also writes CSV itself with --csv; this script reads runs saved as text.)"""
import re
import sys


def collide_bench(lines):
    print("group,function,median_ns,min_ns,true_fraction")
    group = None
    for line in lines:
        if line and not line.startswith(" ") and not re.match(r"^(collide_bench|compiler|CPU|method|min the|builder|\d+ functions)", line):
            group = line.strip()
            continue
        m = re.match(r"^\s+(cd\S+(?: [a-z0-9-]+)?)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$", line)
        if m and group:
            print(f"{group},{m.group(1)},{m.group(2)},{m.group(3)},{m.group(4)}")


def manifold2(lines):
    print("case,collide_ns,box2d_ns,ratio")
    for line in lines:
        m = re.match(r"^(\S.*?)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$", line)
        if m:
            print(f"\"{m.group(1)}\",{m.group(2)},{m.group(3)},{m.group(4)}")


def manifold3(lines):
    print("pair,query,collide_ns,bullet_ns,ccd_gjk_ns,ccd_mpr_ns,fcl_ns")
    for line in lines:
        if line.startswith("| ") and not line.startswith("| pair") and not line.startswith("|---"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            values = [re.sub(r"\s*\(.*\)", "", c).replace("-", "") for c in cells[2:]]
            print(",".join([f"\"{cells[0]}\"", f"\"{cells[1]}\""] + values))


def scenes(lines):
    print("query,collide_ns,peer,peer_function,peer_ns,ratio")
    for line in lines:
        m = re.match(r"^((?:2D|3D) .*?)\s+([\d.]+) (\S+) (.*?)\s+([\d.]+)\s+([\d.]+)\s*$", line)
        if m:
            print(f"\"{m.group(1)}\",{m.group(2)},{m.group(3)},\"{m.group(4)}\",{m.group(5)},{m.group(6)}")


if __name__ == "__main__":
    kind, path = sys.argv[1], sys.argv[2]
    lines = open(path, encoding="utf-8").read().split("\n")
    {"collide_bench": collide_bench, "manifold2": manifold2, "manifold3": manifold3, "scenes": scenes}[kind](lines)
