"""``scanline studio``: a real server process on a free loopback port."""

import subprocess
import sys
import urllib.request

import pytest


def start(*args):
    proc = subprocess.Popen([sys.executable, "-m", "scanline", "studio", "--port", "0", *args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    lines = []
    for line in proc.stdout:
        lines.append(line)
        if "http://" in line:
            break
    return proc, lines


@pytest.mark.parametrize("host, warned", [(None, False), ("127.0.0.2", True)])
def test_the_command_prints_its_address_and_serves(host, warned):
    proc, lines = start(*(["--host", host] if host else []))
    try:
        assert lines, proc.stderr.read()
        url = lines[-1].split()[2]
        assert url.startswith(f"http://{host or '127.0.0.1'}:")
        assert any("not only this machine" in line for line in lines) == warned
        with urllib.request.urlopen(url + "explorer", timeout=60) as r:
            assert r.status == 200 and b"explorer.js" in r.read()
    finally:
        proc.terminate()
        proc.wait(30)
