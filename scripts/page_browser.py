#!/usr/bin/python3
"""parksim's pages (parksim/pages/) in a real browser: Debian's Chromium, headless, driven by
chromedriver through Selenium (scripts/install-deps.sh test installs the three). The page tests
(tests/pages/test_pages.py), the page benchmark (bench/pages/bench_pages.py) and the docs'
screenshots use this one session setup:

    with PageBrowser() as b:
        b.open("out/run/report.html")          # from file://, waits for data-ready="true"
        b.requests_outside("out/run")          # [] : nothing fetched from outside the folder
        b.console_errors()                     # [] : nothing logged as an error
        b.dialogs()                            # [] : no alert, confirm or prompt opened

As a program it takes a screenshot of a page once it is drawn:

    scripts/page_browser.py screenshot out/run/report.html docs/images/page-episode.png
        [--size 1400x1000] [--js 'parksimReplay.seek(5)']

Chromium runs with the flags this machine's closed network needs (no background requests,
no component updates, no sync) and a fresh profile each session."""
import argparse
import json
import os
import pathlib
import sys
import tempfile
import time

from selenium import webdriver
from selenium.common.exceptions import UnexpectedAlertPresentException
from selenium.webdriver.chrome.service import Service

CHROMIUM = os.environ.get("PARKSIM_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("PARKSIM_CHROMEDRIVER", "/usr/bin/chromedriver")
FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--hide-scrollbars", "--force-device-scale-factor=1",
]


class PageError(AssertionError):
    pass


class PageBrowser:
    """One headless Chromium session; pages are opened one after another in it."""

    def __init__(self, width=1400, height=1000):
        self.profile = tempfile.TemporaryDirectory(prefix="parksim-chromium-")
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for flag in FLAGS + ["--user-data-dir=" + self.profile.name,
                             "--window-size=%d,%d" % (width, height)]:
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
        self.driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
        self.driver.set_page_load_timeout(60)
        self._requests = []
        self._console = []
        self._dialogs = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        if self.driver is not None:
            self.driver.quit()
            self.driver = None
        self.profile.cleanup()

    def _drain(self):
        """Moves the browser's logs collected so far into this session's lists."""
        for entry in self.driver.get_log("performance"):
            message = json.loads(entry["message"])["message"]
            if message.get("method") == "Network.requestWillBeSent":
                self._requests.append(message["params"]["request"]["url"])
            elif message.get("method") == "Page.javascriptDialogOpening":
                self._dialogs.append(message["params"].get("message", ""))
        self._console.extend(self.driver.get_log("browser"))

    def open(self, path, timeout_s=60.0):
        """Opens the page at `path` from file:// and waits until it says it is drawn
        (document.body.dataset.ready); returns the seconds that took, from navigation start
        as the page measures it. Raises PageError when the page failed or timed out. The
        requests and console messages checked afterwards are those from here on."""
        self._drain()
        self._requests.clear()
        self._console.clear()
        self._dialogs.clear()
        self.driver.get(pathlib.Path(path).resolve().as_uri())
        return self.wait_ready(path, timeout_s)

    def wait_ready(self, path=None, timeout_s=60.0):
        """Waits until the page at `path` (with None: the page shown) is drawn; returns
        open()'s seconds. After a click on a link, name the page it leads to. A dialog the page
        opens meanwhile (chromedriver closes it) does not stop the wait: dialogs() lists it."""
        want = pathlib.Path(path).resolve().as_uri() if path is not None else None
        deadline = time.monotonic() + timeout_s
        while True:
            try:
                url, ready, failed = self.driver.execute_script(
                    "return [location.href, document.body && document.body.dataset.ready,"
                    " document.body && document.body.dataset.failed]")
            except UnexpectedAlertPresentException:
                url = ready = failed = None
            here = want is None or url == want
            if here and ready == "true":
                break
            if here and failed:
                raise PageError("%s: the page failed: %s" % (url, failed))
            if time.monotonic() > deadline:
                raise PageError("%s: not ready after %.0f s (at %s)" % (path, timeout_s, url))
            time.sleep(0.02)
        return self.driver.execute_script("return window.parksimReadyMs") / 1000.0

    def requests_outside(self, folder):
        """URLs the pages opened since open() requested that are not files in `folder`."""
        self._drain()
        root = pathlib.Path(folder).resolve().as_uri() + "/"
        return [u for u in self._requests if not u.startswith(root)]

    def console_errors(self):
        """Console messages of level SEVERE since open() (exceptions, CSP violations)."""
        self._drain()
        return [e for e in self._console if e["level"] == "SEVERE"]

    def dialogs(self):
        """The messages of the JavaScript dialogs (alert, confirm, prompt) opened since open(),
        from Chromium's own page events."""
        self._drain()
        return list(self._dialogs)

    def js(self, code, *args):
        """Runs `code` in the page; a dialog the page opened first is closed (dialogs() lists
        it) and the code run again."""
        for _ in range(100):
            try:
                return self.driver.execute_script(code, *args)
            except UnexpectedAlertPresentException:
                pass
        raise PageError("the page keeps opening dialogs: %s" % self.dialogs()[-3:])

    def screenshot(self, png):
        self.driver.save_screenshot(str(png))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    shot = sub.add_parser("screenshot", help="a page's screenshot once it is drawn")
    shot.add_argument("page")
    shot.add_argument("png")
    shot.add_argument("--size", default="1400x1000")
    shot.add_argument("--js", default="", help="JavaScript to run before the screenshot")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    with PageBrowser(width, height) as b:
        b.open(args.page)
        if args.js:
            b.js(args.js)
            time.sleep(0.3)
        errors = b.console_errors()
        b.screenshot(args.png)
    if errors:
        print("console errors: %s" % errors, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
