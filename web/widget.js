// <gestura-player>: a signing avatar any page drops in with one script tag.
//
//   <script src="https://SERVER/widget.js" defer></script>
//   <gestura-player text="Hello, how are you?"></gestura-player>       signs the text
//   <gestura-player selection></gestura-player>                         signs the text the reader selects
//
// Attributes: text, selection, server (default: where this script came from), camera (front,
// three-quarter, side, hands, face), speed (0.25–2), width/height via CSS. Methods: say(text),
// sign({sigml|hamnosys}), and postMessage-style post({type: 'sigml', data}). Events: 'ready',
// 'playing' (detail: glosses, duration), 'error' (detail: message). The player runs in an iframe
// of SERVER/embed.html, so the host page needs no three.js and no import map.
(() => {
  const scriptServer = (() => {
    try { return new URL(document.currentScript.src).origin; } catch { return location.origin; }
  })();

  class GesturaPlayer extends HTMLElement {
    static get observedAttributes() { return ['text']; }

    constructor() {
      super();
      this.attachShadow({ mode: 'open' }).innerHTML = `
        <style>
          :host { display: inline-block; width: 320px; height: 400px; position: relative; border-radius: 8px;
                  overflow: hidden; background: #eef1f5; font: 14px system-ui, sans-serif; }
          iframe { border: 0; width: 100%; height: 100%; display: block; }
          .message { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
                     text-align: center; padding: 1rem; color: #7a1d1d; background: #fbeaea; }
          .message[hidden] { display: none; }
        </style>
        <iframe title="Sign language avatar" allow="autoplay"></iframe>
        <div class="message" role="alert" hidden></div>`;
      this.frame = this.shadowRoot.querySelector('iframe');
      this.messageBox = this.shadowRoot.querySelector('.message');
      this.ready = false;
      this.pending = [];
      this.onMessage = (event) => this.fromFrame(event);
      this.onSelection = () => this.signSelection();
    }

    get server() { return (this.getAttribute('server') || scriptServer).replace(/\/$/, ''); }

    async connectedCallback() {
      window.addEventListener('message', this.onMessage);
      if (this.hasAttribute('selection')) {
        document.addEventListener('mouseup', this.onSelection);
        document.addEventListener('keyup', this.onSelection);
      }
      // Is the server there? A clear message beats an empty box.
      const controller = new AbortController();
      const timer = setTimeout(() => controller.abort(), 5000);
      try {
        const r = await fetch(`${this.server}/health`, { signal: controller.signal });
        if (!r.ok) throw new Error(`HTTP ${r.status}`);
      } catch (e) {
        this.showMessage(`The sign language player cannot reach its server (${this.server}). Signing is unavailable for now.`);
        this.dispatchEvent(new CustomEvent('error', { detail: { message: 'unreachable' } }));
        return;
      } finally {
        clearTimeout(timer);
      }
      const query = new URLSearchParams();
      for (const name of ['camera', 'speed']) if (this.hasAttribute(name)) query.set(name, this.getAttribute(name));
      this.frame.src = `${this.server}/embed.html?${query}`;
    }

    disconnectedCallback() {
      window.removeEventListener('message', this.onMessage);
      document.removeEventListener('mouseup', this.onSelection);
      document.removeEventListener('keyup', this.onSelection);
    }

    attributeChangedCallback(name, old, value) {
      if (name === 'text' && value && value !== old) this.say(value);
    }

    showMessage(text) {
      this.messageBox.textContent = text;
      this.messageBox.hidden = false;
    }

    fromFrame(event) {
      if (event.source !== this.frame.contentWindow) return;
      const m = event.data ?? {};
      if (m.type === 'gestura:ready') {
        this.ready = true;
        this.messageBox.hidden = true;
        if (this.hasAttribute('text') && !this.pending.length) this.pending.push({ type: 'text', data: this.getAttribute('text') });
        for (const p of this.pending.splice(0)) this.post(p);
        this.dispatchEvent(new Event('ready'));
      } else if (m.type === 'gestura:playing') {
        this.dispatchEvent(new CustomEvent('playing', { detail: { glosses: m.glosses, duration: m.duration } }));
      } else if (m.type === 'gestura:error') {
        this.dispatchEvent(new CustomEvent('error', { detail: { message: m.message } }));
      }
    }

    // Any message the embedded player takes ({type: 'sigml', data} as for UPF Performs).
    post(message) {
      if (!this.ready) { this.pending.push(message); return; }
      this.frame.contentWindow.postMessage(message, this.server);
    }
    say(text) { this.post({ type: 'text', data: String(text) }); }
    sign({ sigml, hamnosys } = {}) {
      if (sigml) this.post({ type: 'sigml', data: sigml });
      else if (hamnosys) this.post({ type: 'hamnosys', data: hamnosys });
    }

    signSelection() {
      const text = String(window.getSelection?.() ?? '').trim();
      if (!text || text === this.lastSelection) return;
      this.lastSelection = text;
      this.say(text.slice(0, 2000));
    }
  }

  if (!customElements.get('gestura-player')) customElements.define('gestura-player', GesturaPlayer);
})();
