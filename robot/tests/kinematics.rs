//! Forward kinematics against published home positions, inverse against
//! forward for every confdata, the choice of solution and every error.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use rapid_robot::frames::{Tool, WObj};
use rapid_robot::{Conf, JointLimits, ReachError, Robot, model_by_name, models};

fn robot(name: &str) -> Robot {
    Robot::new(model_by_name(name).unwrap_or_else(|| panic!("no model {name}")))
}

/// A small deterministic generator (the same poses in every run).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    (
        (a.translation.vector - b.translation.vector).norm(),
        a.rotation.angle_to(&b.rotation).to_degrees(),
    )
}

#[test]
fn forward_kinematics_meets_every_published_home_position() {
    // tool0 at all axes zero: the home position the model's source gives,
    // with the flange facing forwards (orient [0.707107, 0, 0.707107, 0]).
    let facing = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 90f64.to_radians());
    let mut worst = 0.0f64;
    for m in models() {
        let r = Robot::new(m);
        let home = r.forward(&[0.0; 6]).expect("finite");
        let err = (home.translation.vector - Vector3::from(m.home)).norm();
        worst = worst.max(err);
        assert!(
            err < 0.01,
            "{}: home {:?}, published {:?}",
            m.name,
            home.translation,
            m.home
        );
        assert!(home.rotation.angle_to(&facing) < 1e-9, "{}", m.name);
        assert_eq!(r.conf_of(&[0.0; 6]), Conf::default(), "{}", m.name);
    }
    eprintln!("largest home position error: {worst:.2e} mm");
}

#[test]
fn inverse_meets_forward_on_random_poses_in_every_configuration() {
    let mut rng = Lcg(29);
    let mut worst = (0.0f64, 0.0f64);
    let mut seen = std::collections::HashSet::new();
    for m in models() {
        let r = Robot::new(m);
        let mut tried = 0;
        while tried < 200 {
            let mut j = [0.0; 6];
            for (i, a) in j.iter_mut().enumerate() {
                let [lo, hi] = m.limits[i];
                *a = rng.between(lo + 2.0, hi - 2.0);
            }
            // Away from the wrist singularity and quadrant edges, where
            // several solutions are the same pose.
            if j[4].abs() < 3.0
                || [j[0], j[3], j[5]]
                    .iter()
                    .any(|a| (a / 90.0 - (a / 90.0).round()).abs() < 0.03)
            {
                continue;
            }
            let pose = r.forward(&j).expect("finite");
            let conf = r.conf_of(&j);
            let sol = match r.reach(&pose, Some(&conf)) {
                Ok(s) => s,
                Err(e) => panic!("{}: {j:?} {conf}: {e}", m.name),
            };
            let back = r.forward(&sol.joints).expect("finite");
            let (dp, da) = pose_error(&pose, &back);
            worst = (worst.0.max(dp), worst.1.max(da));
            assert!(
                dp < 1e-6 && da < 1e-6,
                "{}: {j:?} -> {:?}",
                m.name,
                sol.joints
            );
            // Robots whose cfx is not used reach a pose with the same
            // cf1, cf4 and cf6 in two elbow configurations: either will do.
            if m.cfx == rapid_robot::model::Cfx::Arm {
                for (a, b) in j.iter().zip(&sol.joints) {
                    assert!(
                        (a - b).abs() < 1e-6,
                        "{}: {j:?} -> {:?} ({conf})",
                        m.name,
                        sol.joints
                    );
                }
            }
            seen.insert((m.name.clone(), conf.cfx));
            tried += 1;
        }
    }
    eprintln!(
        "round trip: largest errors {:.2e} mm, {:.2e} deg",
        worst.0, worst.1
    );
    // Every arm configuration occurs on the arms that use cfx.
    let irb120: std::collections::HashSet<i32> = seen
        .iter()
        .filter(|(n, _)| n == "IRB 120-3/0.58")
        .map(|(_, c)| *c)
        .collect();
    assert!(irb120.len() >= 6, "{irb120:?}");
}

#[test]
fn confdata_chooses_among_the_solutions() {
    let r = robot("IRB 140-6/0.81");
    // A pose several arm configurations reach within the working ranges:
    // each configuration's solution is the one confdata picks.
    let j = [20.0, 10.0, 20.0, 30.0, 45.0, 60.0];
    let pose = r.forward(&j).expect("a value in a test");
    let mut confs = Vec::new();
    for s in r.arm().inverse(&pose) {
        if rapid_robot::violation(&r.limits, &s).is_some() {
            continue;
        }
        let c = r.conf_of(&s);
        let got = r.reach(&pose, Some(&c)).expect("a value in a test");
        assert_eq!(got.conf, c);
        for (a, b) in s.iter().zip(&got.joints) {
            assert!((a - b).abs() < 1e-6, "{c}: {s:?} {:?}", got.joints);
        }
        confs.push(c.cfx);
    }
    confs.sort();
    assert_eq!(confs, vec![0, 1, 6, 7], "{confs:?}");
    // A configuration with no solution in the working ranges.
    let elbow_down = Conf {
        cf1: 0,
        cf4: 0,
        cf6: 0,
        cfx: 2,
    };
    assert!(r.reach(&pose, Some(&elbow_down)).is_err());
    // Axis 6 one turn back: cf6 picks the turn.
    let want = Conf {
        cf1: 0,
        cf4: 0,
        cf6: -4,
        cfx: 0,
    };
    let s = r.reach(&pose, Some(&want)).expect("a value in a test");
    assert!((s.joints[5] + 300.0).abs() < 1e-6, "{:?}", s.joints);
    // One turn forward is past axis 6's 400 degrees.
    let want = Conf { cf6: 4, ..want };
    match r.reach(&pose, Some(&want)) {
        Err(ReachError::JointLimit {
            axis: 6, angle, by, ..
        }) => {
            assert!((angle - 420.0).abs() < 1e-6 && (by - 20.0).abs() < 1e-6);
        }
        other => panic!("{other:?}"),
    }
    // Without confdata (ConfL\Off), the solution nearest the given joints.
    let s = r
        .reach_near(&pose, None, &[20.0, 10.0, 20.0, 30.0, 45.0, -280.0])
        .expect("a value in a test");
    assert!((s.joints[5] + 300.0).abs() < 1e-6);
}

#[test]
fn every_error_case() {
    let r = robot("IRB 120-3/0.58");
    let down = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 180f64.to_radians());
    // Out of reach: the arm's longest reach is 270 + 309 mm from the shoulder.
    let far = Isometry3::from_parts(Translation3::new(1000.0, 0.0, 290.0), down);
    match r.reach(&far, None) {
        Err(e @ ReachError::OutOfReach { by }) => {
            // The wrist centre at (1000, 0, 362): 1000 - 579.8 mm past reach.
            let forearm = (70.0f64 * 70.0 + 302.0 * 302.0).sqrt();
            let expected: f64 =
                Vector3::new(1000.0f64, 0.0, 290.0 + 72.0 - 290.0).norm() - 270.0 - forearm;
            assert!((by - expected).abs() < 1e-6, "{by} vs {expected}");
            assert_eq!(e.event().number, 50050);
            assert_eq!(e.rapid_error(), "ERR_OUTSIDE_REACH");
        }
        other => panic!("{other:?}"),
    }
    // Beyond axis 1's range (±165): reachable at 170 only.
    let j = [170.0, 0.0, 0.0, 0.0, 30.0, 0.0];
    let pose = r.forward(&j).expect("a value in a test");
    match r.reach(&pose, Some(&r.conf_of(&j))) {
        Err(
            e @ ReachError::JointLimit {
                axis, by, bound, ..
            },
        ) => {
            assert_eq!((axis, bound), (1, 165.0));
            assert!((by - 5.0).abs() < 1e-6, "{by}");
            assert_eq!(e.event().title, "Position outside reach");
            assert_eq!(e.rapid_error(), "ERR_ROBLIMIT");
            assert!(e.to_string().contains("axis 1"), "{e}");
        }
        other => panic!("{other:?}"),
    }
    // The same pose is fine in the other arm configuration (axis 1 at
    // -10, reaching over the top) when the limits allow it: here axis 3's
    // range stops it, so the error stays a joint limit.
    // Reachable, but not in the programmed configuration.
    let j = [30.0, 10.0, 20.0, 40.0, 50.0, 10.0];
    let pose = r.forward(&j).expect("a value in a test");
    let wrong = Conf {
        cf1: 0,
        cf4: 2,
        cf6: 0,
        cfx: 0,
    };
    match r.reach(&pose, Some(&wrong)) {
        Err(e @ ReachError::Configuration { found, .. }) => {
            assert_eq!(found.conf, r.conf_of(&j));
            assert_eq!(e.event().number, 50080);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn moc_bounds_replace_the_data_sheet_limits() {
    let m = model_by_name("IRB 120-3/0.58").expect("a value in a test");
    let limits = JointLimits::of(m).with_moc_bounds(&[
        (Some(-1.0), Some(1.0)),
        (None, None),
        (None, None),
        (None, None),
        (None, None),
        (None, None),
    ]);
    assert!((limits.0[0][1] - 57.29578).abs() < 1e-4);
    let r = Robot::new(m).with_limits(limits);
    let j = [60.0, 0.0, 0.0, 0.0, 30.0, 0.0];
    let pose = r.forward(&j).expect("a value in a test");
    assert!(matches!(
        r.reach(&pose, Some(&r.conf_of(&j))),
        Err(ReachError::JointLimit { axis: 1, .. })
    ));
}

#[test]
fn parallel_arm_robots_measure_axis_3_from_the_horizontal() {
    let r = robot("IRB 2400-10/1.55");
    // Tilting the lower arm forward with axis 3 at zero keeps the forearm
    // horizontal: the TCP moves forward and down only by the lower arm's
    // arc, and the flange keeps facing forwards.
    let home = r.forward(&[0.0; 6]).expect("a value in a test");
    let tilted = r
        .forward(&[0.0, 30.0, 0.0, 0.0, 0.0, 0.0])
        .expect("a value in a test");
    let d = tilted.translation.vector - home.translation.vector;
    let s = 30f64.to_radians();
    assert!((d.x - 705.0 * s.sin()).abs() < 1e-6, "{d:?}");
    assert!((d.z + 705.0 * (1.0 - s.cos())).abs() < 1e-6, "{d:?}");
    assert!(home.rotation.angle_to(&tilted.rotation) < 1e-9);
}

#[test]
fn tool_and_work_object_frames() {
    let r = robot("IRB 1600-6/1.2");
    let tool = Tool {
        robhold: true,
        tframe: Isometry3::translation(0.0, 0.0, 150.0),
    };
    let wobj = WObj {
        robhold: false,
        uframe: Isometry3::from_parts(
            Translation3::new(600.0, -200.0, 300.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 90f64.to_radians()),
        ),
        oframe: Isometry3::translation(10.0, 20.0, 0.0),
    };
    let j = [-10.0, 20.0, 10.0, 30.0, 60.0, -20.0];
    let (target, conf) = r.calc_rob_t(&j, &tool, &wobj).expect("a value in a test");
    let rt = rapid_robot::frames::RobTarget {
        pose: target,
        conf,
        extax: [9e9; 6],
    };
    let s = r
        .calc_joint_t(&rt, &tool, &wobj, true)
        .expect("a value in a test");
    for (a, b) in j.iter().zip(&s.joints) {
        assert!((a - b).abs() < 1e-6, "{j:?} {:?}", s.joints);
    }
    // A stationary tool: the robot carries the work object to the TCP.
    let fixed = Tool {
        robhold: false,
        tframe: Isometry3::translation(900.0, 0.0, 500.0),
    };
    let held = WObj {
        robhold: true,
        uframe: Isometry3::translation(0.0, 0.0, 100.0),
        oframe: Isometry3::identity(),
    };
    let (target, conf) = r.calc_rob_t(&j, &fixed, &held).expect("a value in a test");
    let rt = rapid_robot::frames::RobTarget {
        pose: target,
        conf,
        extax: [9e9; 6],
    };
    let s = r
        .calc_joint_t(&rt, &fixed, &held, true)
        .expect("a value in a test");
    for (a, b) in j.iter().zip(&s.joints) {
        assert!((a - b).abs() < 1e-6, "{j:?} {:?}", s.joints);
    }
}
