// Drives your avatar with your body (realtime-virtual-humans.txt's real-time motion capture): the
// camera's pictures go through MediaPipe Holistic in this page (npm @mediapipe/holistic, served
// from node_modules with its model files: nothing leaves for another site), and the landmarks go
// over the room's WebSocket. The server fits your avatar's arms, hands and head to them and
// everyone in the room sees the pose (docs/api.md, "Driving your avatar with your body").
//
//   const capture = new BodyCapture(room);           // a RoomView that has joined
//   await capture.start(previewVideoElement);        // throws CameraError with a message to show
//   capture.stop();
const HOLISTIC = '/node_modules/@mediapipe/holistic/';
const MAX_RATE = 15;  // landmarks messages a second (the server takes at most 30)

export class CameraError extends Error {}

// What to tell a person whose camera did not start, by the DOMException's name.
function cameraError(e) {
  switch (e?.name) {
    case 'NotAllowedError': case 'SecurityError':
      return new CameraError('The camera was refused. To drive your avatar with your body, allow this page to use the camera (the camera icon in the address bar) and press "Use my camera" again.');
    case 'NotFoundError': case 'OverconstrainedError':
      return new CameraError('No camera was found on this device.');
    case 'NotReadableError': case 'AbortError':
      return new CameraError('The camera is in use by another program, or cannot be read.');
    default:
      return new CameraError(`The camera cannot be started: ${e?.message ?? e}`);
  }
}

let holisticScript = null;
function loadHolistic() {
  holisticScript ??= new Promise((resolve, reject) => {
    const s = document.createElement('script');
    s.src = `${HOLISTIC}holistic.js`;
    s.onload = () => resolve(window.Holistic);
    s.onerror = () => { holisticScript = null; reject(new CameraError('The body tracker (MediaPipe Holistic) cannot be loaded from this server.')); };
    document.head.append(s);
  });
  return holisticScript;
}

const round = (points, digits, visibility = false) => points?.map((p) => {
  const q = [+p.x.toFixed(digits), +p.y.toFixed(digits), +p.z.toFixed(digits)];
  if (visibility) q.push(+Math.min(1, Math.max(0, p.visibility ?? 1)).toFixed(2));
  return q;
}) ?? null;

export class BodyCapture extends EventTarget {
  constructor(room) {
    super();
    this.room = room;
    this.running = false;
    this.sent = 0;
    this.frames = 0;
  }

  async start(video) {
    if (this.running) return;
    if (!navigator.mediaDevices?.getUserMedia) throw new CameraError('This browser lets pages use no camera (a camera needs https or localhost).');
    try {
      this.stream = await navigator.mediaDevices.getUserMedia({ video: { width: 640, height: 480 }, audio: false });
    } catch (e) {
      throw cameraError(e);
    }
    this.video = video ?? document.createElement('video');
    this.video.muted = true;
    this.video.playsInline = true;
    this.video.srcObject = this.stream;
    await this.video.play();
    const Holistic = await loadHolistic();
    if (!this.holistic) {
      this.holistic = new Holistic({ locateFile: (f) => HOLISTIC + f });
      this.holistic.setOptions({ modelComplexity: 0, smoothLandmarks: true, refineFaceLandmarks: false,
                                 minDetectionConfidence: 0.5, minTrackingConfidence: 0.5 });
      this.holistic.onResults((r) => this.results(r));
      await this.holistic.initialize();
    }
    this.running = true;
    this.loop();
  }

  async loop() {
    while (this.running) {
      const began = performance.now();
      try {
        if (this.video.readyState >= 2) await this.holistic.send({ image: this.video });
      } catch (e) {
        this.dispatchEvent(new CustomEvent('error', { detail: e }));
      }
      const wait = 1000 / MAX_RATE - (performance.now() - began);
      await new Promise((r) => setTimeout(r, Math.max(0, wait)));
    }
  }

  results(r) {
    this.frames += 1;
    if (!this.running || !r.poseLandmarks) return;
    const aspect = this.video.videoWidth && this.video.videoHeight ? this.video.videoWidth / this.video.videoHeight : 4 / 3;
    this.room.send({ type: 'landmarks', aspect: +aspect.toFixed(4), pose: round(r.poseLandmarks, 4, true),
                     left: round(r.leftHandLandmarks, 4), right: round(r.rightHandLandmarks, 4), face: round(r.faceLandmarks, 3) });
    this.sent += 1;
    this.dispatchEvent(new CustomEvent('sent', { detail: { frames: this.frames, sent: this.sent } }));
  }

  stop() {
    this.running = false;
    this.stream?.getTracks().forEach((t) => t.stop());
    this.stream = null;
    if (this.video) this.video.srcObject = null;
  }
}
