// The room page: join a room with a name and a look, type to sign
// (the scene and the protocol are in room.js).
import { BodyCapture } from './capture.js';
import { RoomView } from './room.js';

const $ = (id) => document.getElementById(id);
const setStatus = (text, error = false) => { $('status').textContent = text; $('status').classList.toggle('error', error); };
const room = new RoomView($('view'));
window.gesturaRoom = room;  // for tests and the console

const params = new URLSearchParams(location.search);
if (params.get('room')) $('room-name').value = params.get('room');
if (params.get('name')) $('your-name').value = params.get('name');

fetch('/api/looks').then((r) => r.json()).then(({ looks }) => {
  $('look').replaceChildren(...looks.map((l) => Object.assign(document.createElement('option'), { value: l.name, textContent: `${l.name} — ${l.description}` })));
  if (params.get('look')) $('look').value = params.get('look');
  room.preload(['default', $('look').value]).catch(() => {});  // the host and you, ready before joining
}).catch(() => {});

const names = new Map();
function people(state) {
  $('people').replaceChildren(...[...room.figures.values()].filter((f) => f.id !== 'host').map((f) => {
    const li = document.createElement('li');
    li.textContent = `${f.name} (${f.look})${f.connected === false ? ' — away' : ''}${f.id === room.you?.id ? ' — you' : ''}`;
    return li;
  }));
}
room.addEventListener('figure', people);
room.addEventListener('message', ({ detail: m }) => {
  if (m.type === 'welcome') for (const p of m.participants) names.set(p.id, p.name);
  if (m.type === 'joined' || m.type === 'back') names.set(m.participant.id, m.participant.name);
  if (['welcome', 'joined', 'back', 'away', 'left'].includes(m.type)) setTimeout(people, 0);
  if (m.type === 'play') {
    const li = document.createElement('li');
    li.textContent = `${names.get(m.participant) ?? m.participant}: ${m.text} — ${m.glosses.map((g) => g.gloss).join(' ')}`;
    $('log').append(li);
  }
  if (m.type === 'preparing') setStatus('Signing…');
  if (m.type === 'play' && m.participant === room.you?.id) setStatus('Signed. Type more.');
  if (m.type === 'error') setStatus(m.error.field ? `${m.error.field}: ${m.error.message}` : m.error.message, true);
  if (m.type === 'replaced') setStatus('This seat was taken back from another tab or window.', true);
});
room.addEventListener('closed', () => {
  stopCamera();
  $('camera-button').disabled = true;
  $('sign-button').disabled = true;
  $('join-button').disabled = false;
  $('leave-button').disabled = true;
});

$('join-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  setStatus('Joining…');
  try {
    const welcome = await room.join($('room-name').value, { name: $('your-name').value, look: $('look').value });
    setStatus(`In room ${welcome.room}, seat ${welcome.you.seat + 1}. Type text and press Enter.`);
    $('sign-button').disabled = false;
    $('camera-button').disabled = false;
    $('join-button').disabled = true;
    $('leave-button').disabled = false;
  } catch (err) {
    setStatus(err.field ? `${err.field}: ${err.message}` : err.message, true);
  }
});
$('leave-button').addEventListener('click', () => room.leave());
const sign = () => {
  const text = $('text').value;
  if (!text.trim()) { setStatus('Type some text to sign.', true); return; }
  room.say(text);
};
$('say-form').addEventListener('submit', (e) => { e.preventDefault(); sign(); });
$('text').addEventListener('keydown', (e) => { if (e.key === 'Enter' && !e.shiftKey) { e.preventDefault(); sign(); } });

// The camera drives your avatar: Holistic in this page, the landmarks to the room (capture.js).
const capture = new BodyCapture(room);
window.gesturaCapture = capture;  // for tests and the console
const cameraStatus = (text, error = false) => { $('camera-status').textContent = text; $('camera-status').classList.toggle('error', error); };
function stopCamera() {
  capture.stop();
  $('camera-button').setAttribute('aria-pressed', 'false');
  $('camera-button').textContent = 'Use my camera';
  $('camera-preview').hidden = true;
}
capture.addEventListener('sent', ({ detail }) => {
  if (detail.sent === 1) cameraStatus('Your avatar follows your arms, hands and head.');
});
$('camera-button').addEventListener('click', async () => {
  if (capture.running) { stopCamera(); cameraStatus('Camera off.'); return; }
  $('camera-button').disabled = true;
  cameraStatus('Starting the camera and the body tracker…');
  try {
    await capture.start($('camera-preview'));
    $('camera-preview').hidden = false;
    $('camera-button').setAttribute('aria-pressed', 'true');
    $('camera-button').textContent = 'Stop my camera';
    cameraStatus('Camera on: looking for your body…');
  } catch (err) {
    stopCamera();
    cameraStatus(err.message, true);
  } finally {
    $('camera-button').disabled = !room.you;
  }
});
