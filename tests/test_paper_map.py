import pytest

from paper_repro.app import paper_map
from paper_repro.util.registry import CLAIMS, FIGURES, load_all


def test_paper_map_lists_every_label():
    labels = paper_map.labels_of_paper()
    if labels is None:
        pytest.skip("paper source ../shared/paper not present")
    load_all()
    m = paper_map.build(CLAIMS, FIGURES)
    assert [r["label"] for r in m["labels"]] == labels
    row = {r["label"]: r for r in m["labels"]}
    assert "torus_exact" in row["exmp:torus"]["claims"] and row["fig:torus"]["figures"] == ["torus"]
    assert all(f"`{lab}`" in paper_map.markdown(m) for lab in labels)


def test_code_mentions_ignores_plain_words():
    assert paper_map.code_mentions("dimension") == []
    assert "paper_repro/printed/torus.py" in paper_map.code_mentions("exmp:torus")
