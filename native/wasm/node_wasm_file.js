// --pre-js of every wasm target: emscripten 3.1.6 fetches the .wasm whenever a global fetch exists,
// which node 18+ has but cannot use on a file path ("Failed to parse URL"). Under node the module is
// read from disk instead; browsers and workers keep fetch.
if (typeof process === 'object' && process.versions && process.versions.node && !Module['instantiateWasm']) {
  Module['instantiateWasm'] = function (imports, receiveInstance) {
    WebAssembly.instantiate(require('fs').readFileSync(wasmBinaryFile), imports).then(function (r) {
      receiveInstance(r.instance, r.module);
    });
    return {};
  };
}
