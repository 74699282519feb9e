// The player inside the iframe of <gestura-player> (widget.js), or alone at /embed.html?text=...
// It answers the parent's postMessage messages:
//   {type: 'text', data: 'Hello'}        sign English text          (gestura)
//   {type: 'sigml', data: '<sigml>…'}    sign SiGML                  (as UPF Performs' iframe takes it)
//   {type: 'hamnosys', data: '…'}        sign HamNoSys
//   {type: 'speed', data: 0.5}, {type: 'pause'}, {type: 'play'}, {type: 'replay'}
// and tells the parent {type: 'gestura:ready'}, {type: 'gestura:playing', glosses, duration},
// {type: 'gestura:error', message}.
import { Player } from './player.js';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
const player = new Player($('view'));
window.gestura = player;
player.setCamera(params.get('camera') ?? 'front');
if (params.get('speed')) player.setSpeed(Number(params.get('speed')));

const tell = (message) => { if (window.parent !== window) window.parent.postMessage(message, '*'); };
const setStatus = (text, error = false) => { $('status').textContent = text; $('status').classList.toggle('error', error); };

player.addEventListener('gloss', ({ detail }) => { $('gloss').textContent = detail.gloss?.gloss ?? ''; });
player.addEventListener('finished', () => { $('gloss').textContent = ''; });

async function perform(what) {
  setStatus('Signing…');
  try {
    const timeline = await what();
    setStatus('');
    tell({ type: 'gestura:playing', glosses: timeline.glosses ?? [], duration: timeline.duration });
  } catch (e) {
    const message = e.field ? `${e.field}: ${e.message}` : e.message;
    setStatus(message, true);
    tell({ type: 'gestura:error', message });
  }
}

window.addEventListener('message', (event) => {
  const m = event.data;
  if (!m || typeof m !== 'object' || typeof m.type !== 'string') return;
  switch (m.type) {
    case 'text': if (typeof m.data === 'string') perform(() => player.say(m.data)); break;
    case 'sigml': if (typeof m.data === 'string') perform(() => player.sign({ sigml: m.data })); break;
    case 'hamnosys': if (typeof m.data === 'string') perform(() => player.sign({ hamnosys: m.data })); break;
    case 'speed': player.setSpeed(Number(m.data) || 1); break;
    case 'pause': player.pause(true); break;
    case 'play': player.pause(false); break;
    case 'replay': player.replay(); break;
    default: break;
  }
});

$('replay').addEventListener('click', () => player.replay());
$('pause').addEventListener('click', () => {
  const paused = !player.paused;
  player.pause(paused);
  $('pause').setAttribute('aria-pressed', String(paused));
  $('pause').setAttribute('aria-label', paused ? 'Play' : 'Pause');
  $('pause').textContent = paused ? '▶' : '❚❚';
});

player.loadAvatar().then(() => {
  setStatus('');
  tell({ type: 'gestura:ready' });
  if (params.get('text')) perform(() => player.say(params.get('text')));
}).catch((e) => {
  setStatus(e.message, true);
  tell({ type: 'gestura:error', message: e.message });
});
