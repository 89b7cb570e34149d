"""The pages a run maps from files, for doc/memory.md: which libraries hold
the part of the resident set that is not the run's own memory, and for the
largest of them which of its ELF sections (code, or the dynamic symbol
tables the loader reads).

A process's resident set counts the pages of the files it maps (the
libraries' code, read-only data and symbol tables) beside its anonymous
memory. Those pages live in the page cache, once for all processes that map
them; they count in the resident set of each. memory_profile.py runs the
scene, reads /proc/PID/smaps and the present bits of /proc/PID/pagemap
shortly before the run ends (file pages are mapped as the code runs and
seldom dropped, so the last reading holds nearly all of them), and reports
them."""
import collections
import os
import re
import struct
import subprocess
import time

PAGE = 4096


def mappings(smaps):
    """(start, end, offset, path, rss_kb, anonymous_kb) of each mapping."""
    found, current = [], None
    for line in smaps.splitlines():
        m = re.match(r"^([0-9a-f]+)-([0-9a-f]+) \S+ ([0-9a-f]+) \S+ \S+\s*(.*)$",
                     line)
        if m:
            current = [int(m.group(1), 16), int(m.group(2), 16),
                       int(m.group(3), 16), m.group(4).strip(), 0, 0]
            found.append(current)
        elif current and line.startswith("Rss:"):
            current[4] = int(line.split()[1])
        elif current and line.startswith("Anonymous:"):
            current[5] = int(line.split()[1])
    return found


def present_pages(pid, start, end):
    """The page indices (from @p start) of [start, end) that are resident."""
    with open(f"/proc/{pid}/pagemap", "rb") as f:
        f.seek(start // PAGE * 8)
        data = f.read((end - start) // PAGE * 8)
    return [i for i in range(len(data) // 8)
            if struct.unpack_from("<Q", data, 8 * i)[0] >> 63]


def record(command, output, interval=0.5):
    """Runs @p command, its standard output into the file @p output, and
    returns its last readable smaps and, for the file with the most
    resident pages mapped, its path and the file offsets of those pages."""
    with open(output, "w") as out:
        p = subprocess.Popen(command, stdout=out, stderr=subprocess.DEVNULL)
    last = None
    while p.poll() is None:
        try:
            with open(f"/proc/{p.pid}/smaps") as f:
                smaps = f.read()
            files = collections.Counter()
            for start, end, offset, path, rss, anon in mappings(smaps):
                if path.startswith("/"):
                    files[path] += rss - anon
            largest = files.most_common(1)[0][0]
            offsets = [offset + PAGE * i
                       for start, end, offset, path, rss, anon in
                       mappings(smaps) if path == largest
                       for i in present_pages(p.pid, start, end)]
            last = (smaps, largest, offsets)
        except (OSError, IndexError):
            pass  # the process ends while it is read
        time.sleep(interval)
    return last


def sections(path):
    """(name, file offset, size) of the ELF sections of @p path."""
    out = subprocess.run(["readelf", "-SW", path], capture_output=True,
                         text=True).stdout
    return [(m.group(1), int(m.group(2), 16), int(m.group(3), 16))
            for m in re.finditer(r"\]\s+(\S+)\s+\S+\s+[0-9a-f]+\s+([0-9a-f]+)"
                                 r"\s+([0-9a-f]+)", out)]


def by_file(smaps):
    """kB resident from each mapped file, without the pages copied on
    write (anonymous)."""
    files = collections.Counter()
    for start, end, offset, path, rss, anon in mappings(smaps):
        if path.startswith("/"):
            files[path] += rss - anon
    return files


def by_section(path, offsets):
    """kB resident of each ELF section of @p path, from the file offsets of
    its resident pages; a page two sections share counts for the first."""
    found = collections.Counter()
    table = sections(path)
    for o in offsets:
        name = next((n for n, start, size in table
                     if start < o + PAGE and o < start + size), "(headers)")
        found[name] += PAGE // 1024
    sizes = {n: size for n, _, size in table}
    return found, sizes


def page_section(command, output):
    """The section of doc/memory.md on the pages mapped from files, from a
    run of @p command (its standard output into the file @p output)."""
    recorded = record(command, output)
    if not recorded:
        return "(the run ended before its pages could be read)\n"
    smaps, largest, offsets = recorded
    files = by_file(smaps)
    total = sum(files.values())
    rows = ["| file | MB resident |", "|---|---|"]
    for path, kb in files.most_common(8):
        rows.append(f"| `{os.path.basename(path)}` | {kb / 1024:.1f} |")
    rows.append(f"| the other {len(files) - 8} files | "
                f"{(total - sum(k for _, k in files.most_common(8))) / 1024:.1f}"
                " |")
    parts, sizes = by_section(largest, offsets)
    split = ["| section | MB in the file | MB resident |", "|---|---|---|"]
    for name, kb in parts.most_common(8):
        split.append(f"| `{name}` | {sizes.get(name, 0) / 2**20:.1f} | "
                     f"{kb / 1024:.1f} |")
    return (f"Resident pages mapped from files near the end of the run: "
            f"{total / 1024:.0f} MB from {len(files)} files.\n\n"
            + "\n".join(rows) + f"\n\nThose of `{os.path.basename(largest)}` "
            "by ELF section "
            "(`.dynstr` and `.dynsym`: the names and entries of its exported "
            "symbols; `.rela.*`: its relocations; `.text`: its code):\n\n"
            + "\n".join(split) + "\n")
