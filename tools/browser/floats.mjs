// A file's bytes as 32-bit floats (the lab's .f32 pictures). A Buffer that readFileSync returns for a small
// file is a view into a shared 8 KiB pool: its .buffer is the whole pool, so the view's own bytes are copied.
export function floatsOf(bytes) {
  return new Float32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
}
