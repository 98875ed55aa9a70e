//! `WebotsNative`, a camera's Recognition: `wb_camera_recognition_*` for `Camera`, the objects
//! as `CameraRecognitionObject`s built from one call of the C API's Rust twin
//! (`car::camera_values::wb_camera_recognition_get_objects`: the same checks and messages as
//! the C function). Units: m, rad, px, periods in ms.

use jni::JNIEnv;
use jni::errors::Result as JniResult;
use jni::objects::{JObject, JValue};
use jni::sys::{jboolean, jint, jobjectArray};
use sim::devices::RecognitionObject;

use crate::{java_len, tag};

/// The Java class of a recognised object, built by its package-private constructor.
const RECOGNITION_OBJECT: &str = "com/cyberbotics/webots/controller/CameraRecognitionObject";
/// `CameraRecognitionObject(int id, double[] position, double[] orientation, double[] size,
/// int[] positionOnImage, int[] sizeOnImage, double[] colors, String model)`.
const RECOGNITION_OBJECT_NEW: &str = "(I[D[D[D[I[I[DLjava/lang/String;)V";

natives! { "com_cyberbotics_webots_controller_WebotsNative";
    /// `wb_camera_has_recognition`.
    fn cameraHasRecognition(env, device: jint) -> jboolean =>
        jboolean::from(car::wb_camera_has_recognition(tag(device)));
    /// `wb_camera_recognition_enable` (ms).
    fn cameraRecognitionEnable(env, device: jint, period: jint) =>
        car::wb_camera_recognition_enable(tag(device), period);
    /// `wb_camera_recognition_disable`.
    fn cameraRecognitionDisable(env, device: jint) => car::wb_camera_recognition_disable(tag(device));
    /// `wb_camera_recognition_get_sampling_period` (ms).
    fn cameraRecognitionGetSamplingPeriod(env, device: jint) -> jint =>
        car::wb_camera_recognition_get_sampling_period(tag(device));
    /// `wb_camera_recognition_get_number_of_objects`.
    fn cameraRecognitionGetNumberOfObjects(env, device: jint) -> jint =>
        car::wb_camera_recognition_get_number_of_objects(tag(device));
    /// `wb_camera_recognition_has_segmentation`.
    fn cameraRecognitionHasSegmentation(env, device: jint) -> jboolean =>
        jboolean::from(car::wb_camera_recognition_has_segmentation(tag(device)));
    /// `wb_camera_recognition_get_objects` as `CameraRecognitionObject[]` (empty where C returns
    /// NULL; `null` only if the JVM cannot allocate, an exception then pending).
    fn cameraRecognitionGetObjects(env, device: jint) -> jobjectArray => {
        let objects = car::camera_values::wb_camera_recognition_get_objects(tag(device));
        recognition_objects(&mut env, &objects).unwrap_or(std::ptr::null_mut())
    };
}

/// A new `CameraRecognitionObject[]` holding `objects`.
fn recognition_objects(
    env: &mut JNIEnv<'_>,
    objects: &[RecognitionObject],
) -> JniResult<jobjectArray> {
    let class = env.find_class(RECOGNITION_OBJECT)?;
    let array = env.new_object_array(java_len(objects.len())?, &class, JObject::null())?;
    for (index, object) in (0..).zip(objects) {
        // One local frame per object: its arrays and string are freed once it is stored.
        env.with_local_frame(8, |env| -> JniResult<()> {
            let position = [object.position.x, object.position.y, object.position.z];
            let colors: Vec<f64> = object.colors.iter().flatten().copied().collect();
            let position = doubles(env, &position)?;
            let orientation = doubles(env, &object.orientation)?;
            let size = doubles(env, &object.size)?;
            let on_image = ints(env, &object.position_on_image)?;
            let size_on_image = ints(env, &object.size_on_image)?;
            let colors = doubles(env, &colors)?;
            let model = JObject::from(env.new_string(&object.model)?);
            let element = env.new_object(
                RECOGNITION_OBJECT,
                RECOGNITION_OBJECT_NEW,
                &[
                    JValue::Int(object.id),
                    JValue::Object(&position),
                    JValue::Object(&orientation),
                    JValue::Object(&size),
                    JValue::Object(&on_image),
                    JValue::Object(&size_on_image),
                    JValue::Object(&colors),
                    JValue::Object(&model),
                ],
            )?;
            env.set_object_array_element(&array, index, element)
        })?;
    }
    Ok(array.into_raw())
}

/// A new Java `double[]` holding `values`, as a local reference of the current frame.
fn doubles<'l>(env: &mut JNIEnv<'l>, values: &[f64]) -> JniResult<JObject<'l>> {
    let array = env.new_double_array(java_len(values.len())?)?;
    env.set_double_array_region(&array, 0, values)?;
    Ok(array.into())
}

/// A new Java `int[]` holding `values`, as a local reference of the current frame.
fn ints<'l>(env: &mut JNIEnv<'l>, values: &[i32]) -> JniResult<JObject<'l>> {
    let array = env.new_int_array(java_len(values.len())?)?;
    env.set_int_array_region(&array, 0, values)?;
    Ok(array.into())
}
