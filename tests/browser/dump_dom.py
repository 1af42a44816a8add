#!/usr/bin/env python3
"""Prints the DOM of a page as Chromium holds it once loaded, read through the DevTools protocol.

Usage: dump_dom.py CHROMIUM URL [CHROMIUM FLAGS...]

For pages loaded with JavaScript disabled (--blink-settings=scriptEnabled=false): Chromium's own
--dump-dom then prints nothing, since it reads the DOM with a script in the page; the protocol's
DOM.getOuterHTML needs no script. Chromium runs with --remote-debugging-pipe (commands on fd 3,
answers on fd 4, each a JSON text ended by a NUL byte), opens about:blank, and is told to load URL.
"""
import json
import os
import select
import subprocess
import sys
import time


class Chromium:
    def __init__(self, executable, flags):
        self.commands_r, self.commands_w = os.pipe()
        self.answers_r, self.answers_w = os.pipe()

        def child_pipes():
            os.dup2(self.commands_r, 3)
            os.dup2(self.answers_w, 4)

        self.process = subprocess.Popen([executable] + flags + ["--remote-debugging-pipe", "about:blank"],
                                        pass_fds=(3, 4), preexec_fn=child_pipes, stdin=subprocess.DEVNULL,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(self.commands_r)
        os.close(self.answers_w)
        self.buffer = b""
        self.last_id = 0
        self.events = []

    def receive(self, deadline):
        while b"\0" not in self.buffer:
            left = deadline - time.time()
            if left <= 0:
                raise TimeoutError("no answer from Chromium")
            if select.select([self.answers_r], [], [], left)[0]:
                chunk = os.read(self.answers_r, 1 << 20)
                if not chunk:
                    raise EOFError("Chromium closed the DevTools pipe")
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=30):
        self.last_id += 1
        message = {"id": self.last_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.commands_w, json.dumps(message).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            answer = self.receive(deadline)
            if answer.get("id") == self.last_id:
                if "error" in answer:
                    raise RuntimeError("%s: %s" % (method, answer["error"].get("message")))
                return answer["result"]
            self.events.append(answer)

    def wait_for(self, event, timeout=30):
        deadline = time.time() + timeout
        while True:
            for i, message in enumerate(self.events):
                if message.get("method") == event:
                    return self.events.pop(i)
            self.events.append(self.receive(deadline))

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except Exception:  # noqa: BLE001 - it is going away anyway
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: dump_dom.py CHROMIUM URL [CHROMIUM FLAGS...]")
    browser = Chromium(sys.argv[1], sys.argv[3:])
    try:
        page = [t for t in browser.call("Target.getTargets")["targetInfos"] if t["type"] == "page"][0]
        session = browser.call("Target.attachToTarget", {"targetId": page["targetId"], "flatten": True})["sessionId"]
        browser.call("Page.enable", session=session)
        browser.call("Page.navigate", {"url": sys.argv[2]}, session=session)
        browser.wait_for("Page.loadEventFired")
        root = browser.call("DOM.getDocument", {"depth": 0}, session=session)["root"]
        sys.stdout.write(browser.call("DOM.getOuterHTML", {"nodeId": root["nodeId"]}, session=session)["outerHTML"])
        sys.stdout.write("\n")
    finally:
        browser.close()


if __name__ == "__main__":
    main()
