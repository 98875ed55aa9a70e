// What report.html's viewer takes from three.js: the core and two addons, bundled by
// vendor.sh into one script that defines the global `THREE`.
export * from "three";
export { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
export { OrbitControls } from "three/addons/controls/OrbitControls.js";
