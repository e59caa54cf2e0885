"""msmesh.report(): the HTML report of the CLI's --report, for meshes and runs from Python."""

import numpy as np
import pytest

import msmesh


@pytest.fixture(scope="module")
def run():
    V, F = msmesh.make_shape("fandisk", 4)
    noisy = msmesh.add_noise(V, F, sigma=0.3, seed=7)
    V_new, rep = msmesh.denoise(noisy, F, preset="cad", normal_iterations=5, vertex_iterations=5)
    return V, F, noisy, V_new, rep


def test_denoise_report(tmp_path, run):
    V, F, noisy, V_new, rep = run
    path = tmp_path / "r.html"
    assert msmesh.report(path, [("input", noisy, F), dict(name="result", V=V_new, F=F, v=rep["v"])], truth=(V, F),
                         run=rep, title="denoise <test>", notes=["hello"]) is None
    html = path.read_text()
    for part in ("<!DOCTYPE html>", "denoise &lt;test&gt;", '"name":"input"', '"name":"result"', '"name":"truth"',
                 '"initial_mesh":1', '"initial_color":"error"', "MSAE (x1e-3)", "<h2>Parameters</h2>",
                 "alpha (\u03b1)", "Normal filtering (Algorithm 1)", "Vertex update (Algorithm 2)", "hello",
                 "Three.js Authors", '"field":"'):
        assert part in html, part
    for part in ("<script src", "<link", "url(http"):
        assert part not in html, part
    # Returned as a string without a path; the same page.
    assert msmesh.report(None, [("input", noisy, F), dict(name="result", V=V_new, F=F, v=rep["v"])],
                         truth=(V, F), run=rep, title="denoise <test>", notes=["hello"]) == html


def test_segment_report(run):
    V, F, *_ = run
    if not hasattr(msmesh, "segment"):
        pytest.skip("built without segmentation")
    labels, rep = msmesh.segment(V, F)
    html = msmesh.report(None, [dict(name="mesh", V=V, F=F, labels=labels, v=rep["v"])], run=rep)
    assert '"initial_color":"labels"' in html and '"labels":"' in html
    assert "angle: faces whose regularised normals" in html  # the segment table's parameter help


def test_report_checks(tmp_path, run):
    V, F, *_ = run
    with pytest.raises(msmesh.InvalidInputError, match=r"meshes\[0\] F"):
        msmesh.report(None, [("a", V, F + 10**6)])
    with pytest.raises(msmesh.InvalidInputError, match="unknown keys"):
        msmesh.report(None, [dict(name="a", V=V, F=F, colour=1)])
    with pytest.raises(msmesh.InvalidInputError, match="highlighted"):
        msmesh.report(None, [dict(name="a", V=V, F=F, highlighted=np.ones(3, bool))])
    with pytest.raises(msmesh.InvalidInputError, match="edge_field size|v"):
        msmesh.report(None, [dict(name="a", V=V, F=F, v=np.ones(3))])
    with pytest.raises(msmesh.InvalidInputError, match="initial_mesh"):
        msmesh.report(None, [("a", V, F)], initial_mesh=3)
    with pytest.raises(msmesh.InvalidInputError, match="run"):
        msmesh.report(None, [("a", V, F)], run=[1])
    with pytest.raises(msmesh.IoError):
        msmesh.report(tmp_path / "no" / "such" / "r.html", [("a", V, F)])
