//! Move times against hand computation.

use nalgebra::{Isometry3, Translation3};
use rapid_robot::motion::{
    self, AXIS_ACCEL_TIME, Ends, Limit, Path, Speed, TCP_ACCEL, cartesian_move, joint_move,
};
use rapid_robot::{Robot, model_by_name};

fn irb120() -> Robot {
    Robot::new(model_by_name("IRB 120-3/0.58").expect("a value in a test"))
}

const FINE: Ends = Ends::new(true, true);

fn speed(v_tcp: f64) -> Speed {
    Speed {
        v_tcp,
        v_ori: 500.0,
        v_leax: 5000.0,
        v_reax: 1000.0,
    }
}

#[test]
fn trapezoid_and_triangle_profiles() {
    // 100 mm at 100 mm/s, 10 m/s²: 0.5 mm to accelerate, 0.5 to stop.
    assert!((motion::profile(100.0, 100.0, 10_000.0, true, true) - 1.01).abs() < 1e-12);
    // Flying through (zones on both sides): distance over speed.
    assert!((motion::profile(100.0, 100.0, 10_000.0, false, false) - 1.0).abs() < 1e-12);
    // Too short to reach the speed: a triangle, 2 * sqrt(d / a).
    let t = motion::profile(10.0, 5000.0, 10_000.0, true, true);
    assert!((t - 2.0 * (10.0f64 / 10_000.0).sqrt()).abs() < 1e-12);
    assert_eq!(motion::profile(0.0, 100.0, 1.0, true, true), 0.0);
}

#[test]
fn joint_move_time_is_the_slowest_axis() {
    let r = irb120();
    // Axis 1 turns 90 degrees at 250 deg/s, reaching it in 0.2 s (25
    // degrees): 40 degrees of cruise (0.16 s) and two ramps of 0.2 s.
    let t = joint_move(
        &r,
        &[0.0; 6],
        &[90.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        &speed(5000.0),
        FINE,
    );
    assert_eq!(t.limit, Limit::Axis(1));
    assert!(
        (t.seconds - (40.0 / 250.0 + 2.0 * AXIS_ACCEL_TIME)).abs() < 1e-9,
        "{t:?}"
    );
    // At v1000 the TCP's chord (2 * 374 * sin 45 = 528.9 mm) takes longer.
    let t = joint_move(
        &r,
        &[0.0; 6],
        &[90.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        &speed(1000.0),
        FINE,
    );
    let chord = 2.0 * 374.0 * 45f64.to_radians().sin();
    let ramp = 1000.0 * 1000.0 / (2.0 * TCP_ACCEL);
    assert_eq!(t.limit, Limit::Tcp);
    assert!((t.seconds - ((chord - 2.0 * ramp) / 1000.0 + 2.0 * 1000.0 / TCP_ACCEL)).abs() < 1e-9);
}

#[test]
fn linear_move_time_and_path() {
    let r = irb120();
    let start = [0.0, 10.0, 10.0, 0.0, 60.0, 0.0];
    let from = r.forward(&start).expect("a value in a test");
    let to = Translation3::new(0.0, 100.0, 0.0) * from;
    let m = cartesian_move(
        &r,
        &start,
        &Isometry3::from(to),
        Path::Line,
        None,
        &speed(100.0),
        FINE,
    )
    .expect("a value in a test");
    // 100 mm at v100 with 0.5 mm ramps: 1.01 s, the TCP the limit.
    assert_eq!(m.time.limit, Limit::Tcp);
    assert!((m.time.seconds - 1.01).abs() < 1e-9, "{:?}", m.time);
    let end = r.forward(&m.end.joints).expect("a value in a test");
    assert!((end.translation.vector - to.translation.vector).norm() < 1e-6);
    // A zone at the end: no deceleration.
    let zone = Ends::new(true, false);
    let m = cartesian_move(
        &r,
        &start,
        &Isometry3::from(to),
        Path::Line,
        None,
        &speed(100.0),
        zone,
    )
    .expect("a value in a test");
    assert!((m.time.seconds - 1.005).abs() < 1e-9);
}

#[test]
fn circular_move_follows_the_arc() {
    let r = irb120();
    let start = [0.0, 10.0, 10.0, 0.0, 60.0, 0.0];
    let from = r.forward(&start).expect("a value in a test");
    let p = from.translation.vector;
    // A half circle of radius 50 mm: 157.08 mm at v100.
    let via = p + nalgebra::Vector3::new(50.0, 50.0, 0.0);
    let to = Isometry3::from_parts(
        (p + nalgebra::Vector3::new(0.0, 100.0, 0.0)).into(),
        from.rotation,
    );
    let m = cartesian_move(&r, &start, &to, Path::Arc(via), None, &speed(100.0), FINE)
        .expect("a value in a test");
    let length = std::f64::consts::PI * 50.0;
    assert!(
        (m.time.seconds - ((length - 1.0) / 100.0 + 0.02)).abs() < 1e-9,
        "{:?}",
        m.time
    );
}

#[test]
fn a_linear_move_out_of_reach_stops() {
    let r = irb120();
    let start = [0.0, 10.0, 10.0, 0.0, 60.0, 0.0];
    let from = r.forward(&start).expect("a value in a test");
    let to = Translation3::new(800.0, 0.0, 0.0) * from;
    assert!(
        cartesian_move(
            &r,
            &start,
            &Isometry3::from(to),
            Path::Line,
            None,
            &speed(100.0),
            FINE
        )
        .is_err()
    );
}
