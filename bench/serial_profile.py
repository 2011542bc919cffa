#!/usr/bin/env python3
"""Where a run on several threads is serial (issue 30): which stages ran while no other thread of the
process did. Reads `perf script -F tid,time,ip,sym` of a run recorded with
`perf record -F 499 --call-graph dwarf,8192`, bins the samples by time (--bin-ms, 4), calls a bin
serial when one thread alone was sampled in it, and charges each sample to the innermost frame that
matches one of the STAGE regular expressions (else to its own function). Prints, per stage, its share
of all samples in serial bins and in bins where several threads ran. Meaningful on a quiet machine
only: under load a thread that has work may wait for a core, and its bins look serial.

usage: perf script -i perf.data -F tid,time,ip,sym | bench/serial_profile.py [--bin-ms MS] STAGE...
example (bench/README.md, Threads):
  perf record -F 499 --call-graph dwarf,8192 -o p.data holefill fill -q h20k.ply -o out.ply
  perf script -i p.data -F tid,time,ip,sym | bench/serial_profile.py load_mesh stitch_borders \\
      find_islands MeshFaceIndex::MeshFaceIndex fill_apart splice_patch write_mesh
"""
import collections
import re
import sys


def read_samples(lines, stages):
    """(thread id, time in s, stage) per sample of perf script's output."""
    samples, head, frames = [], None, []

    def flush():
        if head is None:
            return
        stage = next((s.pattern for f in frames for s in stages if s.search(f)), None)
        samples.append((head[0], head[1], stage or "(other) " + (frames[0] if frames else "?")))

    for line in lines:
        if not line.strip():
            flush()
            head, frames = None, []
        elif not line[0].isspace():
            fields = line.split()
            head = (fields[0], float(fields[1].rstrip(":")))
        else:  # a frame: address, then the function
            frames.append(line.strip().split(None, 1)[-1])
    flush()
    return samples


def main(argv):
    bin_ms = 4.0
    if argv[:1] == ["--bin-ms"]:
        bin_ms, argv = float(argv[1]), argv[2:]
    samples = read_samples(sys.stdin, [re.compile(a) for a in argv])
    if not samples:
        sys.exit("serial_profile.py: no samples on standard input")
    threads_in_bin = collections.defaultdict(set)
    for tid, time, _ in samples:
        threads_in_bin[int(time * 1000 / bin_ms)].add(tid)
    serial, parallel = collections.Counter(), collections.Counter()
    for tid, time, stage in samples:
        alone = len(threads_in_bin[int(time * 1000 / bin_ms)]) == 1
        (serial if alone else parallel)[stage] += 1
    total = len(samples)
    share = lambda n: f"{100.0 * n / total:5.1f} %"
    print(f"{total} samples: serial {share(sum(serial.values()))}, "
          f"several threads {share(sum(parallel.values()))}")
    print("| stage | serial | several threads |")
    print("|---|---|---|")
    for stage, n in sorted(serial.items(), key=lambda item: -item[1])[:25]:
        print(f"| {stage[:70]} | {share(n)} | {share(parallel[stage])} |")


if __name__ == "__main__":
    main(sys.argv[1:])
