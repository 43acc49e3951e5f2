// --pre-js of the node programs (hbc.js, hbc_tests.js): the process's environment reaches getenv()
// (HBC_THREADS, HBC_DATA_DIR, GTEST_*), which emscripten otherwise fills with defaults of its own.
Module['preRun'] = (Module['preRun'] || []).concat([function () {
  if (typeof process === 'object' && process.env) Object.assign(ENV, process.env);
}]);
