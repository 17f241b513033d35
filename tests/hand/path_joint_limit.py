# The continuous joints of an IRB 120 moving its TCP straight down with the
# orientation kept, from a start near the wrist singularity, by the OPW inverse
# kinematics of palletizing_corners.py (no joint limits: the branch nearest the
# previous sample). Used by tests/conformance/motion_path_joint_limit and
# crates/rapid-motion/tests/plan.rs (`a_linear_move_whose_axis_…`, `near_the_wrist_…`).
import os
import numpy as np
here = os.path.dirname(os.path.abspath(__file__))
exec(open(os.path.join(here, 'palletizing_corners.py')).read().split("R = np.diag")[0])
for start in ([0, 0, 0, 45, 3, 0], [0, 0, 0, 60, 10, 0]):
    q0 = np.array(start, dtype=float)
    p0, R0 = fk(q0)
    seed = q0
    print('from', start)
    for mm in range(0, 61, 6):
        seed = ik(p0 - np.array([0, 0, float(mm)]), R0, seed)
        print(f'  {mm:2d} mm down: {np.round(seed, 2)}')
