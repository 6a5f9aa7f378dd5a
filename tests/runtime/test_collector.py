"""The one way the runtime quiets the cyclic garbage collector
(:mod:`al2py_runtime.collector`): each strength changes what it says and
puts back exactly what it found."""

import gc

import pytest
from al2py_runtime import collector


@pytest.fixture
def saved_gc():
    thresholds, enabled = gc.get_threshold(), gc.isenabled()
    yield
    gc.set_threshold(*thresholds)
    (gc.enable if enabled else gc.disable)()


def test_raised_thresholds_are_put_back(saved_gc):
    gc.set_threshold(700, 10, 10)
    quiet = collector.Quiet()
    assert gc.get_threshold() == collector.THRESHOLDS
    assert gc.isenabled()
    quiet.restore()
    assert gc.get_threshold() == (700, 10, 10)
    gc.set_threshold(5, 6, 7)
    quiet.restore()  # once only: a later change stays
    assert gc.get_threshold() == (5, 6, 7)


def test_thresholds_higher_than_the_raised_ones_are_kept(saved_gc):
    gc.set_threshold(200_000, 10, 5000)
    with collector.Quiet():
        assert gc.get_threshold() == (200_000, 50, 5000)
    assert gc.get_threshold() == (200_000, 10, 5000)


def test_thresholds_are_put_back_when_the_object_goes(saved_gc):
    gc.set_threshold(700, 10, 10)
    quiet = collector.Quiet()
    del quiet  # a workspace whose import failed
    assert gc.get_threshold() == (700, 10, 10)


def test_paused_enables_again_only_what_was_enabled(saved_gc):
    gc.enable()
    with collector.paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.disable()
    with collector.paused():
        assert not gc.isenabled()
    assert not gc.isenabled()


def test_paused_is_undone_by_an_exception(saved_gc):
    gc.enable()
    with pytest.raises(ZeroDivisionError), collector.paused():
        raise ZeroDivisionError
    assert gc.isenabled()


def test_settled_pauses_then_freezes_what_it_made(saved_gc):
    gc.enable()
    gc.unfreeze()
    with collector.settled():
        assert not gc.isenabled()
        made = [[i] for i in range(1000)]
    assert gc.isenabled()
    assert gc.get_freeze_count() >= len(made)
    gc.unfreeze()


def test_settled_gives_back_what_was_frozen_when_it_fails(saved_gc):
    gc.enable()
    gc.freeze()  # an earlier statement's objects
    assert gc.get_freeze_count() > 0
    with pytest.raises(KeyboardInterrupt), collector.settled():
        raise KeyboardInterrupt
    assert gc.isenabled()
    assert gc.get_freeze_count() == 0


def test_settled_inside_paused_stays_paused(saved_gc):
    gc.enable()
    with collector.paused():
        with collector.settled():
            assert not gc.isenabled()
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.unfreeze()
