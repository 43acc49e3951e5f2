"""The window's side of a build in steps (plan/steps.py): the timer that wakes the modal operator
and the progress (the window manager's counter, the status bar's text, the header of the area the
build was started from)."""

from __future__ import annotations

import time

import bpy

#: Seconds between the timer's events, and the main-thread work one event may do before the window
#: redraws (the Blender-side writing comes in chunks of about this much).
TICK = 0.02
BUDGET = 0.1


#: The most main-thread work one event may do, however slow the window draws (Esc answers within it).
MAX_BUDGET = 1.0


def budget(last_step_end: float) -> float:
    """The main-thread work for this event: BUDGET, or as long as the window took to draw and wait
    since the last step (up to MAX_BUDGET), so that a window slow to draw (software GL on a busy
    machine) does not take most of the build's time."""
    return min(max(BUDGET, time.perf_counter() - last_step_end), MAX_BUDGET)


def in_window(context) -> bool:
    """Whether a build here runs in steps: a window to redraw and a timer to step with (not in
    background mode, nor from a script's context without a window)."""
    return not bpy.app.background and getattr(context, "window", None) is not None


class WindowProgress:
    """Progress of one stepped build in the window that started it, until `end`."""

    def __init__(self, context, title: str):
        self.title = title
        self.wm = context.window_manager
        self.window = context.window
        self.workspace = context.workspace
        self.area = context.area
        self.wm.progress_begin(0, 100)
        self.timer = self.wm.event_timer_add(TICK, window=self.window)
        self.text, self.percent = "", -1

    def show(self, fraction: float, message: str):
        """The build at `fraction` (0..1) doing `message`: counter, status bar, header, 3D views."""
        percent = int(100 * min(max(fraction, 0.0), 1.0))
        if percent != self.percent:
            self.percent = percent
            self.wm.progress_update(percent)
        text = f"{self.title}: {message} ({percent}%) - Esc cancels"
        if text != self.text:
            self.text = text
            try:
                self.workspace.status_text_set(text)
                if self.area is not None:
                    self.area.header_text_set(text)
            except (AttributeError, ReferenceError, RuntimeError):
                pass  # the area or workspace went away: the counter still shows
        # The 3D views are not tagged: Blender redraws them when the scene changes, and a redraw
        # for nothing costs seconds in a busy software-GL window.

    def end(self):
        if self.timer is None:
            return
        self.wm.event_timer_remove(self.timer)
        self.timer = None
        self.wm.progress_end()
        try:
            self.workspace.status_text_set(None)
            if self.area is not None:
                self.area.header_text_set(None)
        except (AttributeError, ReferenceError, RuntimeError):
            pass
