"""plan.session.dropped_text: the import report's words for what skip_invalid dropped."""
from hybrid_base_complex.plan import session


def test_dropped_text():
    assert session.dropped_text(None) == ""
    assert session.dropped_text({"count": 0, "by_reason": {}, "cells": []}) == ""
    one = {"count": 1, "by_reason": {"few_faces": 1}, "cells": [{"id": 3, "reason": "few_faces", "line": 9}]}
    assert session.dropped_text(one) == "dropped 1 cell (1 few_faces)"
    two = {"count": 3, "by_reason": {"few_faces": 2, "open_cells": 1}, "cells": []}
    assert session.dropped_text(two) == "dropped 3 cells (2 few_faces, 1 open_cells)"
