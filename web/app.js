// The page: a form whose text the avatar signs, playback and camera controls, the glosses shown
// as they are signed, a dictionary. Everything the server does is in player.js.
import { Player } from './player.js';

const $ = (id) => document.getElementById(id);
const status = $('status');
const setStatus = (text, error = false) => { status.textContent = text; status.classList.toggle('error', error); };

const player = new Player($('view'));
window.gestura = player;  // for tests and the console

player.addEventListener('timeline', ({ detail }) => {
  const list = $('glosses');
  list.replaceChildren(...(detail.glosses ?? []).map((g, i) => {
    const li = document.createElement('li');
    li.textContent = g.gloss;
    li.dataset.index = i;
    li.title = `${g.start.toFixed(2)}–${g.end.toFixed(2)} s: ${g.source}`;
    return li;
  }));
});
player.addEventListener('gloss', ({ detail }) => {
  for (const li of $('glosses').children) li.classList.toggle('now', Number(li.dataset.index) === detail.index);
  if (detail.gloss) $('now-signing').textContent = detail.gloss.gloss;
});
player.addEventListener('finished', () => setStatus('Done. Replay with R, or type more.'));

async function sign(text) {
  if (!text.trim()) { setStatus('Type some text to sign.', true); return; }
  setStatus('Signing…');
  const started = performance.now();
  try {
    const timeline = await player.say(text, { speed: 1 });
    const ms = Math.round(performance.now() - started);
    setStatus(`Signing ${timeline.glosses.length} glosses (${timeline.duration.toFixed(1)} s; answered in ${ms} ms, ${Math.round(player.lastClipBytes / 1024)} KB).`);
    $('pause').textContent = 'Pause';
    $('pause').setAttribute('aria-pressed', 'false');
  } catch (e) {
    setStatus(e.field ? `${e.field}: ${e.message}` : e.message, true);
  }
}

$('say-form').addEventListener('submit', (e) => { e.preventDefault(); sign($('text').value); });
$('text').addEventListener('keydown', (e) => {
  if (e.key === 'Enter' && !e.shiftKey) { e.preventDefault(); sign($('text').value); }
});
$('pause').addEventListener('click', () => {
  const paused = !player.paused;
  player.pause(paused);
  $('pause').textContent = paused ? 'Play' : 'Pause';
  $('pause').setAttribute('aria-pressed', String(paused));
});
$('replay').addEventListener('click', () => player.replay());
$('back').addEventListener('click', () => player.step(-1));
$('forward').addEventListener('click', () => player.step(1));
$('speed').addEventListener('input', (e) => {
  const v = Number(e.target.value);
  player.setSpeed(v);
  $('speed-value').textContent = `${v}×`;
  e.target.setAttribute('aria-valuetext', `${v} times`);
});
for (const b of document.querySelectorAll('[data-camera]')) b.addEventListener('click', () => player.setCamera(b.dataset.camera));
// Keys in the 3D view: Space pause, R replay, , and . step.
const view = $('view');
view.tabIndex = 0;
view.addEventListener('keydown', (e) => {
  if (e.key === ' ') { e.preventDefault(); $('pause').click(); }
  else if (e.key === 'r') $('replay').click();
  else if (e.key === ',') player.step(-1);
  else if (e.key === '.') player.step(1);
});

// Dictionary: search the lexicon, play a sign from its notation.
$('dict-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const list = $('dict-results');
  const q = $('dict-query').value.trim();
  try {
    const r = await player.fetchOk(`/api/lexicon?limit=30&q=${encodeURIComponent(q)}`);
    const { entries, total } = await r.json();
    list.replaceChildren(...entries.map((entry) => {
      const li = document.createElement('li');
      const play = document.createElement('button');
      play.type = 'button';
      play.textContent = `▶ ${entry.gloss}`;
      play.setAttribute('aria-label', `Play the sign ${entry.gloss}`);
      // HamNoSys and SiGML entries are played from their notation; others by their word through say.
      const word = entry.keywords?.[0]?.word ?? entry.gloss.toLowerCase();
      const source = entry.notation_kind === 'hamnosys' ? () => player.sign({ hamnosys: entry.notation })
        : entry.notation_kind === 'sigml' ? () => player.sign({ sigml: entry.notation }) : () => player.say(word);
      play.addEventListener('click', () => source().then(() => setStatus(`Signing ${entry.gloss}.`)).catch((err) => setStatus(err.message, true)));
      const notation = document.createElement('code');
      notation.textContent = entry.notation_kind === 'hamnosys' ? ` ${entry.notation} ` : ' ';
      const about = document.createElement('span');
      about.textContent = [entry.language, (entry.keywords ?? []).map((k) => k.word).join(', '), entry.source].filter(Boolean).join(' · ');
      li.append(play, notation, about);
      return li;
    }));
    if (total > entries.length) list.append(Object.assign(document.createElement('li'), { textContent: `… ${total - entries.length} more` }));
    if (!entries.length) list.append(Object.assign(document.createElement('li'), { textContent: 'No sign found.' }));
  } catch (err) {
    setStatus(err.message, true);
  }
});

// The avatar's look: the built-in looks the server lists.
fetch('/api/looks').then((r) => r.json()).then(({ looks }) => {
  $('look').replaceChildren(...looks.map((l) => Object.assign(document.createElement('option'), { value: l.name, textContent: `${l.name} — ${l.description}` })));
}).catch(() => {});
$('look').addEventListener('change', (e) => {
  setStatus('Loading the avatar…');
  player.setLook(e.target.value).then(() => setStatus(`Ready: ${e.target.value}. Type text and press Enter.`))
    .catch((err) => setStatus(`Cannot load the avatar: ${err.message}`, true));
});

player.loadAvatar().then(() => setStatus('Ready. Type text and press Enter.'))
  .catch((e) => setStatus(`Cannot load the avatar: ${e.message}`, true));
