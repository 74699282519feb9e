// A shared signing room (docs/api.md, "Rooms"): every participant's avatar and the host in one
// three.js scene, driven by the server's messages over the room's WebSocket. The state is the
// server's: seats, looks, what plays since when, where the host looks; this only shows it.
//
//   const room = new RoomView(element);
//   await room.join('lobby', { name: 'Ana', look: 'ana' });
//   room.say('Hello, how are you?');
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import * as SkeletonUtils from 'three/addons/utils/SkeletonUtils.js';

// Bind a clip's face track (the stand-in mesh "face_weights") to each of the avatar's morph meshes.
function bindClip(clip, morphMeshes) {
  const tracks = [];
  for (const track of clip.tracks) {
    if (!track.name.startsWith('face_weights.')) { tracks.push(track); continue; }
    for (const mesh of morphMeshes) {
      const copy = track.clone();
      copy.name = `${mesh.uuid}.morphTargetInfluences`;
      tracks.push(copy);
    }
  }
  return new THREE.AnimationClip(clip.name, clip.duration, tracks);
}

function label(text) {
  const canvas = document.createElement('canvas');
  canvas.width = 256; canvas.height = 64;
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(canvas), depthTest: false }));
  sprite.scale.set(0.8, 0.2, 1);
  sprite.userData.draw = (t, colour = '#24324a') => {
    const g = canvas.getContext('2d');
    g.clearRect(0, 0, 256, 64);
    g.fillStyle = 'rgba(255,255,255,0.85)';
    g.fillRect(0, 8, 256, 48);
    g.fillStyle = colour;
    g.font = 'bold 30px system-ui, sans-serif';
    g.textAlign = 'center';
    g.fillText(t, 128, 44, 248);
    sprite.material.map.needsUpdate = true;
  };
  sprite.userData.draw(text);
  return sprite;
}

export class RoomView extends EventTarget {
  constructor(container, { server = '' } = {}) {
    super();
    this.server = server.replace(/\/$/, '');
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    this.canvas = this.renderer.domElement;
    container.appendChild(this.canvas);
    this.container = container;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xeef1f5);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 2.2));
    const key = new THREE.DirectionalLight(0xffffff, 2.0);
    key.position.set(1.5, 4, 4);
    this.scene.add(key);
    const floor = new THREE.Mesh(new THREE.CircleGeometry(3.4, 64), new THREE.MeshStandardMaterial({ color: 0xd5dae2 }));
    floor.rotation.x = -Math.PI / 2;
    floor.position.z = -0.6;
    this.scene.add(floor);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.05, 60);
    this.camera.position.set(0, 2.3, 3.6);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.target.set(0, 1.1, -1.3);
    this.controls.enableDamping = true;
    this.controls.update();
    this.templates = new Map();  // look → Promise of the loaded glTF scene
    this.figures = new Map();    // participant id ('host' for the host) → figure
    this.offset = null;          // server time − local time, seconds (best of the pings)
    this.bestRtt = Infinity;
    this.clock = new THREE.Clock();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
    this.renderer.setAnimationLoop(() => this.frame());
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  // The server's clock now, in seconds (its messages' "time", a clip's "start").
  serverNow() { return performance.now() / 1000 + (this.offset ?? 0); }

  template(look) {
    if (!this.templates.has(look)) {
      this.templates.set(look, (async () => {
        const response = await fetch(`${this.server}/api/avatar.glb?look=${encodeURIComponent(look)}`);
        if (!response.ok) throw new Error(`the avatar ${look} cannot be loaded (HTTP ${response.status})`);
        return (await new GLTFLoader().parseAsync(await response.arrayBuffer(), '')).scene;
      })());
    }
    return this.templates.get(look);
  }

  // Downloads looks and compiles their shaders ahead of joining, so that a room full of avatars does
  // not stall the page when it is entered (shader compilation takes long on software GL).
  async preload(looks) {
    const scene = new THREE.Scene();
    scene.add(...this.scene.children.filter((o) => o.isLight).map((l) => l.clone()));
    for (const look of looks) scene.add(SkeletonUtils.clone(await this.template(look)));
    if (this.renderer.compileAsync) await this.renderer.compileAsync(scene, this.camera);
    else this.renderer.compile(scene, this.camera);
    this.renderer.render(scene, this.camera);  // textures uploaded too
  }

  async addFigure(id, p) {
    if (this.figures.has(id)) return this.figures.get(id);
    const figure = { id, name: p.name, look: p.look, seat: p.seat, root: null, mixer: null, action: null, clip: null,
                     pose: null, poseUntil: 0, target: null, label: null, ready: null };
    this.figures.set(id, figure);
    figure.ready = (async () => {
      const root = SkeletonUtils.clone(await this.template(p.look));
      root.position.set(...p.position);
      root.rotation.y = p.yaw;
      figure.root = root;
      figure.morphMeshes = [];
      root.traverse((o) => { if (o.morphTargetInfluences) figure.morphMeshes.push(o); });
      figure.mixer = new THREE.AnimationMixer(root);
      figure.label = label(p.name);
      figure.label.position.set(0, 2.1, 0);
      root.add(figure.label);
      if (!this.figures.has(id)) return figure;  // left while loading
      this.scene.add(root);
      this.dispatchEvent(new CustomEvent('figure', { detail: { id } }));
      return figure;
    })();
    return figure;
  }

  removeFigure(id) {
    const f = this.figures.get(id);
    this.figures.delete(id);
    if (f?.root) this.scene.remove(f.root);
  }

  // Connects and joins; resolves with the welcome message. A token kept from an earlier visit (this
  // tab's sessionStorage) takes the same seat back.
  join(room, { name, look = 'default', reconnect = true } = {}) {
    this.roomName = room;
    const base = (this.server || location.origin).replace(/^http/, 'ws');
    const key = `gestura-room-token:${room}`;
    return new Promise((resolve, reject) => {
      const ws = new WebSocket(`${base}/ws/room/${encodeURIComponent(room)}`);
      this.ws = ws;
      let welcomed = false;
      ws.onopen = () => {
        const token = reconnect ? sessionStorage.getItem(key) : null;
        ws.send(JSON.stringify(token ? { type: 'join', token } : { type: 'join', name, look }));
        this.ping();
        this.pinger = setInterval(() => this.ping(), 2000);
      };
      ws.onmessage = (e) => {
        const m = JSON.parse(e.data);
        if (m.type === 'error' && !welcomed && m.error?.field === 'token') {
          sessionStorage.removeItem(key);  // the seat has gone: join afresh
          ws.send(JSON.stringify({ type: 'join', name, look }));
          return;
        }
        if (m.type === 'welcome') {
          welcomed = true;
          sessionStorage.setItem(key, m.you.token);
          this.you = m.you;
          resolve(m);
        } else if (m.type === 'error' && !welcomed) {
          reject(Object.assign(new Error(m.error.message), { field: m.error.field }));
        }
        this.handle(m);
      };
      ws.onclose = () => {
        clearInterval(this.pinger);
        if (!welcomed) reject(new Error('the room cannot be reached'));
        this.dispatchEvent(new CustomEvent('closed'));
      };
    });
  }

  send(message) { if (this.ws?.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(message)); }
  ping() { this.send({ type: 'ping', t: performance.now() / 1000 }); }
  say(text, speed = 1) { this.send({ type: 'say', text, speed }); }
  leave() { this.send({ type: 'leave' }); sessionStorage.removeItem(`gestura-room-token:${this.roomName}`); this.ws?.close(); }

  handle(m) {
    switch (m.type) {
      case 'pong': {
        // Offset from the round trip with the least delay (the server stamped its time half-way).
        const now = performance.now() / 1000, rtt = now - m.t;
        if (rtt <= this.bestRtt * 1.5 || this.offset === null) {
          this.bestRtt = Math.min(this.bestRtt, rtt);
          this.offset = m.time - (m.t + now) / 2;
        }
        break;
      }
      case 'welcome':
        this.welcome = m;
        this.offset ??= m.time - performance.now() / 1000;
        for (const id of [...this.figures.keys()]) if (id !== 'host' && !m.participants.some((p) => p.id === id)) this.removeFigure(id);
        for (const p of m.participants) this.addFigure(p.id, p).then((f) => this.mark(f, p.connected));
        this.drawSeats(m.seat_places ?? []);
        this.addFigure('host', { ...m.host, seat: -1 }).then(() => this.hostLook(m.host));
        for (const play of m.playing) this.play(play);
        for (const [id, rotations] of Object.entries(m.poses ?? {})) this.pose(id, rotations);
        break;
      case 'joined': case 'back':
        this.addFigure(m.participant.id, m.participant).then((f) => this.mark(f, true));
        break;
      case 'away':
        if (this.figures.has(m.participant)) this.mark(this.figures.get(m.participant), false);
        break;
      case 'left':
        this.removeFigure(m.participant);
        break;
      case 'play': this.play(m); break;
      case 'pose': this.pose(m.participant, m.rotations); break;
      case 'host': this.hostLook(m); break;
      default: break;
    }
    this.dispatchEvent(new CustomEvent('message', { detail: m }));
  }

  mark(figure, connected) {
    figure.connected = connected;
    figure.label?.userData.draw(connected ? figure.name : `${figure.name} (away)`, connected ? '#24324a' : '#888');
  }

  // A clip everyone starts at the server time `start`: fetched, then played from where it is now.
  async play(m) {
    const figure = this.figures.get(m.participant);
    if (!figure) return;
    const response = await fetch(this.server + m.url);
    if (!response.ok) return;
    const gltf = await new GLTFLoader().parseAsync(await response.arrayBuffer(), '');
    await figure.ready;
    if (figure.action) { figure.action.stop(); figure.mixer.uncacheAction(figure.action.getClip()); }
    figure.action = figure.mixer.clipAction(bindClip(gltf.animations[0], figure.morphMeshes));
    figure.action.setLoop(THREE.LoopOnce, 1);
    figure.action.clampWhenFinished = true;
    figure.clip = { start: m.start, duration: m.duration, glosses: m.glosses, text: m.text };
    figure.pose = null;
    this.dispatchEvent(new CustomEvent('play', { detail: { participant: m.participant, text: m.text } }));
  }

  // Joint rotations from a body in front of a camera (or the host's gaze): set on the bones.
  async pose(id, rotations) {
    const figure = this.figures.get(id);
    if (!figure) return;
    await figure.ready;
    figure.pose = rotations;
    figure.poseUntil = this.serverNow() + 1.0;
  }

  // The host's message: where it stands and where its head and eyes turn, or a walk (m.walk: the
  // world's walk cycle as a clip whose root moves in world space, from m.walk.start).
  async hostLook(m) {
    const host = this.figures.get('host');
    if (!host) return;
    await host.ready;
    host.target = m.rotations ?? {};
    host.lookAt = m.look_at ?? null;
    if (m.walk) return this.hostWalk(host, m.walk);
    if (m.position && !host.walk) {
      host.root.position.set(...m.position);
      host.root.rotation.y = m.yaw ?? 0;
    }
  }

  async hostWalk(host, w) {
    const response = await fetch(this.server + w.url);
    if (!response.ok) return;
    const gltf = await new GLTFLoader().parseAsync(await response.arrayBuffer(), '');
    if (host.walkAction) { host.walkAction.stop(); host.mixer.uncacheAction(host.walkAction.getClip()); }
    host.walkAction = host.mixer.clipAction(bindClip(gltf.animations[0], host.morphMeshes));
    host.walkAction.setLoop(THREE.LoopOnce, 1);
    host.walkAction.clampWhenFinished = true;
    host.walk = w;
    this.drawPath(w.path);
  }

  // The seats' places on the floor (the host walks around them) and the host's planned path.
  drawSeats(places) {
    if (this.seatMarks) return;
    this.seatMarks = new THREE.Group();
    const material = new THREE.MeshStandardMaterial({ color: 0xb9c1cd });
    for (const p of places) {
      const mark = new THREE.Mesh(new THREE.RingGeometry(p.radius * 0.8, p.radius, 32), material);
      mark.rotation.x = -Math.PI / 2;
      mark.position.set(p.position[0], 0.005, p.position[2]);
      this.seatMarks.add(mark);
    }
    this.scene.add(this.seatMarks);
  }

  drawPath(points) {
    if (this.pathLine) this.scene.remove(this.pathLine);
    if (!points?.length) return;
    const geometry = new THREE.BufferGeometry().setFromPoints(points.map((p) => new THREE.Vector3(p[0], 0.01, p[2])));
    this.pathLine = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: 0x3d6fb6 }));
    this.scene.add(this.pathLine);
  }

  // World position of a joint of a participant's avatar ('host' for the host), metres, as the
  // scene stands at this moment (the animations brought up to the server's clock first).
  jointPosition(id, joint) {
    this.update(0);
    const node = this.figures.get(id)?.root?.getObjectByName(joint);
    if (!node) return null;
    const p = node.getWorldPosition(new THREE.Vector3());
    return [p.x, p.y, p.z];
  }

  frame() {
    this.update(this.clock.getDelta());
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }

  // Every avatar to where it is at the server's present time: clips at their clip time, body poses
  // and the host's gaze eased toward their targets over dt seconds.
  update(dt) {
    const now = this.serverNow();
    const q = new THREE.Quaternion();
    for (const f of this.figures.values()) {
      if (!f.root) continue;
      if (f.walk && f.walkAction) {
        // The walk clip moves the root in world space: the figure stands at the origin meanwhile.
        const t = now - f.walk.start;
        if (t < 0) {
          f.root.position.set(...f.walk.from.position);
          f.root.rotation.y = f.walk.from.yaw;
        } else if (t <= f.walk.duration) {
          f.root.position.set(0, 0, 0);
          f.root.rotation.y = 0;
          if (!f.walkAction.isRunning()) f.walkAction.play();
          f.walkAction.time = t;
          f.mixer.update(0);
          const hips = f.root.getObjectByName('humanoid_root');
          if (hips && f.label) f.label.position.set(hips.position.x, 2.1, hips.position.z);  // the name above the walker
          continue;  // the head follows the walk; the gaze comes on arrival
        } else {
          f.walkAction.stop();
          f.mixer.update(0);
          f.root.position.set(...f.walk.to.position);
          f.root.rotation.y = f.walk.to.yaw;
          f.walk = null;
          f.label?.position.set(0, 2.1, 0);
          if (this.pathLine) { this.scene.remove(this.pathLine); this.pathLine = null; }
        }
      }
      if (f.action && f.clip) {
        const t = now - f.clip.start;
        if (t >= 0 && t <= f.clip.duration + 0.5) {
          if (!f.action.isRunning() && !f.action.paused) f.action.play();
          f.action.time = Math.min(t, f.clip.duration);
          f.mixer.update(0);
        } else if (t > f.clip.duration + 0.5) {
          f.action.stop();  // back to rest
          f.mixer.update(0);
          f.clip = null;
        }
      }
      if (f.pose && now < f.poseUntil) {
        for (const [name, r] of Object.entries(f.pose)) {
          const bone = f.root.getObjectByName(name);
          if (bone) bone.quaternion.slerp(q.set(r[0], r[1], r[2], r[3]), 1 - Math.exp(-dt * 20));
        }
      }
      if (f.target) {
        for (const [name, r] of Object.entries(f.target)) {
          const bone = f.root.getObjectByName(name);
          if (bone) bone.quaternion.slerp(q.set(r[0], r[1], r[2], r[3]), 1 - Math.exp(-dt * 6));
        }
      }
    }
  }
}
