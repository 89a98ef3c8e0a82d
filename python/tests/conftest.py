"""The package's tests run as the crate's do: Vulkan validation on (any
message fails the run at the end), a cache of their own."""

import os
import tempfile

os.environ.setdefault("BLACKHOLE_VALIDATION", "1")
os.environ.setdefault("XDG_CACHE_HOME", tempfile.mkdtemp(prefix="blackhole-pytest-"))
os.environ.setdefault("LP_NUM_THREADS", "4")

import pytest  # noqa: E402

import blackhole  # noqa: E402


@pytest.fixture(scope="session")
def renderer():
    r = blackhole.Renderer()
    yield r
    assert r.validation_counts() == (0, 0), "validation messages"
    r.close()
