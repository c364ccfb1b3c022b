//! Inverse kinematics per target: the work `rapid check` does for each move
//! of a task whose robot is known.

use rapid_robot::{Conf, Robot, model_by_name};

fn main() {
    divan::main();
}

fn targets(robot: &Robot) -> Vec<(nalgebra::Isometry3<f64>, Conf)> {
    // Reachable poses spread over the working range (a fixed grid, so runs
    // compare).
    let mut out = Vec::new();
    for a1 in [-120.0, -40.0, 0.0, 50.0, 130.0] {
        for a2 in [-30.0, 0.0, 40.0] {
            for a3 in [-60.0, 0.0, 30.0] {
                for a5 in [-70.0, 30.0, 90.0] {
                    let j = [a1, a2, a3, 25.0, a5, -40.0];
                    if let Some(p) = robot.forward(&j) {
                        out.push((p, robot.conf_of(&j)));
                    }
                }
            }
        }
    }
    out
}

#[divan::bench(args = ["IRB 120-3/0.58", "IRB 2400-10/1.55", "IRB 6700-200/2.60"])]
fn reach_with_conf(bencher: divan::Bencher<'_, '_>, name: &str) {
    let Some(model) = model_by_name(name) else {
        return;
    };
    let robot = Robot::new(model);
    let targets = targets(&robot);
    let mut i = 0;
    bencher.bench_local(|| {
        let (pose, conf) = &targets[i % targets.len()];
        i += 1;
        divan::black_box(robot.reach(divan::black_box(pose), Some(conf)).is_ok())
    });
}
