# lifetime: views alias the live arrays and keep them alive; closed Sims
# raise; creating and deleting Sims does not leak
import gc

import numpy as np
import pytest

import mjbuoy


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_views_alias_the_live_arrays(wavy):
    sim = mjbuoy.Sim(wavy)
    qpos = sim.qpos
    sim.step(10)
    assert np.shares_memory(qpos, sim.qpos)  # no copies
    assert np.array_equal(qpos, sim.qpos)
    qpos[2] = 1.0  # a write lands in d->qpos
    assert sim.qpos[2] == 1.0


def test_deleting_a_sim_whose_views_are_held_is_safe(wavy):
    sim = mjbuoy.Sim(wavy)
    sim.step(5)
    q = sim.qpos
    expect = q.copy()
    del sim
    gc.collect()
    # the view keeps the scene alive: still readable and writable
    assert np.array_equal(q, expect)
    q[:] = 0.5
    assert q.sum() == 0.5 * q.size


def test_closed_sim_raises(wavy):
    sim = mjbuoy.Sim(wavy)
    x = sim.body_xpos
    sim.close()
    assert sim.closed
    for use in (lambda: sim.step(), lambda: sim.qpos, lambda: sim.time, lambda: sim.wrench(),
                lambda: sim.sea_height(0, 0), lambda: sim.reset(), lambda: sim.render(64, 64)):
        with pytest.raises(mjbuoy.Error, match="this Sim is closed"):
            use()
    assert x.shape == (2, 3)  # the view held across close() stays valid
    sim.close()  # twice is fine
    with mjbuoy.Sim(wavy) as s:
        s.step()
    assert s.closed


def test_many_sims_do_not_leak(wavy):
    # what one live scene costs (model, data, mjbuoy state), measured with 20
    # held at once; then 300 created and deleted must not keep a tenth of
    # that each. Warm up first (allocator pools, first-use allocations).
    for _ in range(20):
        mjbuoy.Sim(wavy).step(2)
    gc.collect()
    base = rss_kib()
    held = [mjbuoy.Sim(wavy) for _ in range(20)]
    per_sim = (rss_kib() - base) / len(held)
    del held
    gc.collect()
    assert per_sim > 50, f"one scene costs only {per_sim:.0f} KiB: the measure cannot see a leak"
    before = rss_kib()
    for _ in range(300):
        s = mjbuoy.Sim(wavy)
        s.step(2)
        v = s.qpos  # a view, dropped with the Sim
        del s, v
    gc.collect()
    grown = rss_kib() - before
    print(f"one scene {per_sim:.0f} KiB; RSS grew {grown} KiB over 300 Sims")
    assert grown < 0.1 * 300 * per_sim, f"RSS grew {grown} KiB over 300 Sims ({per_sim:.0f} each)"
