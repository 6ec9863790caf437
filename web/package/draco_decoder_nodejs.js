// draco3d's file name for the decoder module factory (same as
// require('draco3d-uv').createDecoderModule).
module.exports = require('./draco3d.js').createDecoderModule;
