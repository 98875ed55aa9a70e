//! `WebotsNative`, a lidar's point cloud: `wb_lidar_*point_cloud*` and
//! `wb_lidar_get_number_of_points` for `Lidar`, the points as `LidarPoint`s built from one
//! call of the C API's Rust twin (`car::lidar_values`: the same checks and messages as the C
//! function). Units: m, s.

use jni::JNIEnv;
use jni::errors::Result as JniResult;
use jni::objects::{JObject, JValue};
use jni::sys::{jboolean, jint, jobjectArray};

use crate::{java_len, tag};

/// The Java class of a lidar point.
const LIDAR_POINT: &str = "com/cyberbotics/webots/controller/LidarPoint";
/// `LidarPoint(float x, float y, float z, int layerId, float time)`.
const LIDAR_POINT_NEW: &str = "(FFFIF)V";

natives! { "com_cyberbotics_webots_controller_WebotsNative";
    /// `wb_lidar_enable_point_cloud`.
    fn lidarEnablePointCloud(env, device: jint) => car::wb_lidar_enable_point_cloud(tag(device));
    /// `wb_lidar_disable_point_cloud`.
    fn lidarDisablePointCloud(env, device: jint) => car::wb_lidar_disable_point_cloud(tag(device));
    /// `wb_lidar_is_point_cloud_enabled`.
    fn lidarIsPointCloudEnabled(env, device: jint) -> jboolean =>
        jboolean::from(car::wb_lidar_is_point_cloud_enabled(tag(device)));
    /// `wb_lidar_get_number_of_points`.
    fn lidarGetNumberOfPoints(env, device: jint) -> jint => car::wb_lidar_get_number_of_points(tag(device));
    /// `wb_lidar_get_point_cloud` as `LidarPoint[]` (m), layer after layer; `null` where C
    /// returns NULL.
    fn lidarGetPointCloud(env, device: jint) -> jobjectArray =>
        lidar_points(&mut env, car::lidar_values::point_cloud(tag(device)).as_deref());
    /// `wb_lidar_get_layer_point_cloud` as `LidarPoint[]` (m); `null` where C returns NULL.
    fn lidarGetLayerPointCloud(env, device: jint, layer: jint) -> jobjectArray =>
        lidar_points(&mut env, car::lidar_values::layer_point_cloud(tag(device), layer).as_deref());
}

/// A new `LidarPoint[]` holding `points`; `null` for `None` or when the JVM cannot allocate
/// it.
fn lidar_points(env: &mut JNIEnv<'_>, points: Option<&[car::WbLidarPoint]>) -> jobjectArray {
    points
        .and_then(|points| point_array(env, points).ok())
        .unwrap_or(std::ptr::null_mut())
}

/// A new `LidarPoint[]` holding `points`.
fn point_array(env: &mut JNIEnv<'_>, points: &[car::WbLidarPoint]) -> JniResult<jobjectArray> {
    let class = env.find_class(LIDAR_POINT)?;
    let array = env.new_object_array(java_len(points.len())?, &class, JObject::null())?;
    for (index, p) in (0..).zip(points) {
        let point = env.new_object(
            &class,
            LIDAR_POINT_NEW,
            &[
                JValue::Float(p.x),
                JValue::Float(p.y),
                JValue::Float(p.z),
                JValue::Int(p.layer_id),
                JValue::Float(p.time),
            ],
        )?;
        env.set_object_array_element(&array, index, &point)?;
        // Freed at once: a cloud has more points than a native frame guarantees references.
        env.delete_local_ref(point)?;
    }
    Ok(array.into_raw())
}
