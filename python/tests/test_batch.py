# mjbuoy.Batch: n worlds stepped on a thread pool, against single Sims
import numpy as np
import pytest

import mjbuoy


def run_sim(model, seed, actions, steps):
    sim = mjbuoy.Sim(model, seed=seed)
    q = []
    for a in actions[:steps]:
        sim.ctrl[:] = a
        sim.step()
        q.append(sim.qpos.copy())
    return np.array(q), sim


def test_identical_seeds_are_bit_identical_to_one_sim(wavy):
    # the same scene and seed must give the same bits whichever thread steps
    # it (docs/robustness.md: cpu results are bit-identical across threads)
    model = wavy
    n, steps = 8, 150
    rng = np.random.default_rng(3)
    batch = mjbuoy.Batch(model, n, seeds=[11] * n, threads=4)
    actions = rng.uniform(-300, 300, size=(steps, batch.nu))
    ref, sim = run_sim(model, 11, actions, steps)
    for t in range(steps):
        qpos, qvel, sens, wrench = batch.step(np.tile(actions[t], (n, 1)), wrench=True)
        for i in range(n):
            assert np.array_equal(qpos[i], ref[t]), (t, i)
    np.testing.assert_array_equal(qvel, np.tile(sim.qvel, (n, 1)))
    np.testing.assert_array_equal(wrench, np.tile(sim.wrench(), (n, 1, 1)))


def test_different_seeds_differ_and_each_matches_its_sim(wavy):
    model = wavy
    batch = mjbuoy.Batch(model, 3, seeds=np.array([1, 2, 3]), threads=2)  # numpy ints too
    for _ in range(100):
        qpos, _, _ = batch.step(np.zeros((3, batch.nu)))
    # different random phases move the buoys differently
    assert not np.array_equal(qpos[0], qpos[1]) and not np.array_equal(qpos[1], qpos[2])
    assert np.abs(qpos[0] - qpos[1]).max() > 1e-6
    ref, _ = run_sim(model, 2, np.zeros((100, batch.nu)), 100)
    assert np.array_equal(qpos[1], ref[-1])


def test_reset_mask_resets_only_masked_worlds(wavy):
    batch = mjbuoy.Batch(wavy, 4, seeds=[5, 6, 7, 8])
    q0, _, _ = batch.reset()
    for _ in range(50):
        q, _, _ = batch.step(np.zeros((4, batch.nu)))
    mask = np.array([True, False, True, False])
    qr, _, _ = batch.reset(mask)
    np.testing.assert_array_equal(qr[mask], q0[mask])  # back to the model's initial state
    np.testing.assert_array_equal(qr[~mask], q[~mask])  # untouched
    # time sums 50 steps of 2 ms in floating point
    np.testing.assert_allclose(batch.time, [0.0, 0.1, 0.0, 0.1], rtol=1e-12, atol=0)


def test_actions_are_checked(models):
    batch = mjbuoy.Batch(str(models / "motorboat.xml"), 2)
    with pytest.raises(ValueError, match=r"actions: shape \(2, 3\), expected \(2, 1\)"):
        batch.step(np.zeros((2, 3)))
    with pytest.raises(ValueError, match=r"actions: shape \(2,\), expected \(2, 1\)"):
        batch.step(np.zeros(2))
    with pytest.raises(TypeError, match="actions: got None"):
        batch.step(None)
    with pytest.raises(TypeError, match="actions: dtype <U1 is not numeric"):
        batch.step(np.array([["a"], ["b"]]))
    with pytest.raises(ValueError, match="actions: element 1 is nan"):
        batch.step(np.array([[1.0], [np.nan]]))
    with pytest.raises(TypeError, match=r"seeds\[1\] is not an int"):
        mjbuoy.Batch(str(models / "motorboat.xml"), 2, seeds=[1, 2.5])
    with pytest.raises(ValueError, match="seeds has 3 values for n = 2"):
        mjbuoy.Batch(str(models / "motorboat.xml"), 2, seeds=[1, 2, 3])
    with pytest.raises(ValueError, match=r"mask: shape \(3,\), expected \(2,\)"):
        batch.reset([True, False, True])
    # ints and non-contiguous arrays are read as float64
    wide = np.zeros((2, 4))
    wide[:, 2] = 50
    q, _, _ = batch.step(wide[:, 2:3][:, ::1])
    q2, _, _ = batch.step(np.array([[50], [50]], dtype=np.int32))
    assert q.shape == (2, batch.nq) and np.array_equal(q2[0], q2[1])
