// three.js render targets and passes the page builds its buffers with: float targets, multi-attachment
// targets with a float depth texture (as the lab's framebuffers), and the depth min/max pyramid built the
// way WebGL 2 allows.
import * as THREE from "three";

export function floatTarget(width, height, options = {}) {
  return new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    generateMipmaps: false,
    depthBuffer: false,
    ...options,
  });
}

// A target with `count` float colour attachments and a float depth texture, as the lab's framebuffers.
export function layerTarget(width, height, count) {
  return floatTarget(width, height, {
    count,
    depthBuffer: true,
    depthTexture: new THREE.DepthTexture(width, height, THREE.FloatType),
  });
}

export function setFilter(texture, filter) {
  texture.minFilter = filter;
  texture.magFilter = filter;
}

export function rawMaterial(vertexShader, fragmentShader, uniforms, options = {}) {
  return new THREE.RawShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader, fragmentShader, uniforms, ...options });
}

// The depth min/max pyramids of width x height depth buffers: levels halve (floor, at least 1) down to 1x1,
// as snell::gpu::DepthPyramid's. WebGL 2 cannot render one level of a texture while sampling another level
// of it, so each level is drawn into a target of its own (shaders/pyramid.frag) and copied into its level
// of a mip-chained target (shaders/copy.frag). `draw(object, target, level)` renders; `quad(material)` is a
// full-screen triangle.
export class Pyramids {
  constructor(width, height, src, constants, draw, quad) {
    this.sizes = [[width, height]];
    while (this.sizes.at(-1)[0] > 1 || this.sizes.at(-1)[1] > 1)
      this.sizes.push([Math.max(1, this.sizes.at(-1)[0] >> 1), Math.max(1, this.sizes.at(-1)[1] >> 1)]);
    this.levelTargets = this.sizes.map(([w, h]) => floatTarget(w, h));
    this.pass = quad(rawMaterial(src["fullscreen.vert"], src["pyramid.frag"], {
      source: { value: null },
      fromDepth: { value: 1 },
      zNear: { value: constants.zNear },
      zFar: { value: constants.zFar },
      emptyDepth: { value: 0 },
    }, { depthTest: false, depthWrite: false }));
    this.copy = quad(rawMaterial(src["fullscreen.vert"], src["copy.frag"], { source: { value: null } },
      { depthTest: false, depthWrite: false }));
    this.width = width;
    this.height = height;
    this.draw = draw;
  }

  target() {
    const t = floatTarget(this.width, this.height, { minFilter: THREE.NearestMipmapNearestFilter });
    t.texture.mipmaps = this.sizes.map(([width, height]) => ({ width, height }));  // three.js: a level per entry
    return t;
  }

  // `depthTexture`'s pyramid into `pyramid` (a target()); emptyDepth: the depth of "nothing there".
  build(depthTexture, emptyDepth, pyramid) {
    const u = this.pass.material.uniforms;
    u.emptyDepth.value = emptyDepth;
    for (let lod = 0; lod < this.sizes.length; ++lod) {
      u.source.value = lod === 0 ? depthTexture : this.levelTargets[lod - 1].texture;
      u.fromDepth.value = lod === 0 ? 1 : 0;
      this.draw(this.pass, this.levelTargets[lod]);
      this.copy.material.uniforms.source.value = this.levelTargets[lod].texture;
      pyramid.viewport.set(0, 0, this.sizes[lod][0], this.sizes[lod][1]);
      this.draw(this.copy, pyramid, lod);
    }
  }
}
