// draco3d's file name for the encoder module factory (same as
// require('draco3d-uv').createEncoderModule).
module.exports = require('./draco3d.js').createEncoderModule;
