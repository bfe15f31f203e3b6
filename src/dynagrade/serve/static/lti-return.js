// The deep-linking answer goes back to the course platform as soon as the page loads
// (templates/lti_placed.html; its button does the same without JavaScript).
document.getElementById("lti-return").submit();
