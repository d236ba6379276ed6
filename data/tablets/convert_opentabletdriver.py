#!/usr/bin/env python3
"""Converts OpenTabletDriver tablet configurations (JSON, LGPL-3.0 data) into rows of
models.tsv, the tablet model table Impasto reads (docs/hid.md).

    data/tablets/convert_opentabletdriver.py OTD_CONFIG_DIR > rows.tsv

One row per digitizer identifier: VID:PID, Impasto's name for the report parser, extents
(mm and lines), pressure maximum, the initialisation (string descriptors to read, output
reports to send, padded to the output report length) and the device string a model is told
apart by (a prefix, or several separated by '|'; conditions that are not simple prefixes are
left out)."""
import base64
import json
import pathlib
import re
import sys

PARSERS = {  # OpenTabletDriver's parser -> (Impasto protocol, reports tilt)
    "UCLogic.UCLogicReportParser": ("uclogic", "no"),
    "UCLogic.UCLogicTiltReportParser": ("uclogic", "yes"),
    "XP_Pen.XP_PenReportParser": ("xp-pen", "yes"),
    "Veikk.VeikkV1ReportParser": ("veikk-v1", "no"),
    "Wacom.IntuosV2.IntuosV2ReportParser": ("wacom-ff0d", "yes"),
    "Wacom.IntuosV2.WacomDriverIntuosV2ReportParser": (None, None),  # Wacom's own driver
    "OpenTabletDriver.Plugin.Tablet.TabletReportParser": ("hid", "yes"),
}


def protocol_of(parser):
    for suffix, value in PARSERS.items():
        if parser.endswith(suffix):
            return value
    raise SystemExit(f"unknown parser {parser}")


def prefixes(pattern):
    """'HUION_T(167|205)_\\d{6}$' -> 'HUION_T167_|HUION_T205_'; None if not a plain prefix."""
    pattern = pattern.lstrip("^")
    pattern = re.sub(r"\\d\{\d+\}\$$", "", pattern).rstrip("$")
    m = re.fullmatch(r"([A-Za-z0-9_\-.]*)\(([A-Za-z0-9|]+)\)([A-Za-z0-9_\-.]*)", pattern)
    if m:
        return "|".join(m.group(1) + alt + m.group(3) for alt in m.group(2).split("|"))
    if re.fullmatch(r"[A-Za-z0-9_\-.]+", pattern):
        return pattern
    return None


def number(value):
    return f"{value:g}"


def main():
    folder = pathlib.Path(sys.argv[1])
    for path in sorted(folder.glob("*.json")):
        config = json.loads(path.read_text())
        digitizer = config["Specifications"]["Digitizer"]
        pen = config["Specifications"]["Pen"]
        for ident in config["DigitizerIdentifiers"]:
            protocol, tilt = protocol_of(ident["ReportParser"])
            if protocol is None:
                continue
            init = [f"string:{i:02x}" for i in ident.get("InitializationStrings", [])]
            for report in ident.get("OutputInitReport", []):
                data = base64.b64decode(report)
                data += bytes(max(0, ident.get("OutputReportLength", len(data)) - len(data)))
                init.append("output:" + data.hex())
            match = "-"
            for index, pattern in ident.get("DeviceStrings", {}).items():
                simple = prefixes(pattern)
                if simple:
                    match = f"string:{int(index):02x}={simple}"
                    break
            print("\t".join([
                f"{ident['VendorID']:04x}", f"{ident['ProductID']:04x}", protocol, tilt,
                number(digitizer["Width"]), number(digitizer["Height"]),
                str(digitizer["MaxX"]), str(digitizer["MaxY"]), str(pen["MaxPressure"]),
                ",".join(init) or "-", match, f'"{config["Name"]}"',
                f"opentabletdriver:{path.name}"]))


if __name__ == "__main__":
    main()
